; Two globals' arithmetic pushed for more arithmetic (`r = (a + b) * 2`), not stored at once:
; base code that the machine fuses at load into ADDIGG, SUBIGG, ADDFGG, SUBFGG and MULFGG
; (vm/fused.def). x = 17, y = 5 (int); f = 1.5, h = 4.0 (float); every result is exact.
.global int "x" 1
.global int "y" 1
.global float "f" 1
.global float "h" 1
.global int "sum2" 1
.global int "diff2" 1
.global float "fsum2" 1
.global float "fdiff2" 1
.global float "fprod2" 1
.const float 1.5
.const float 4.0
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 17
  STG x
  PUSHI 5
  STG y
  PUSHK 0
  STG f
  PUSHK 1
  STG h
  LDG x
  LDG y
  ADDI
  PUSHI 2
  MULI
  STG sum2         ; (17 + 5) * 2 = 44
  LDG x
  LDG y
  SUBI
  PUSHI 2
  MULI
  STG diff2        ; (17 - 5) * 2 = 24
  LDG f
  LDG h
  ADDF
  LDG f
  MULF
  STG fsum2        ; (1.5 + 4.0) * 1.5 = 8.25
  LDG f
  LDG h
  SUBF
  LDG h
  MULF
  STG fdiff2       ; (1.5 - 4.0) * 4.0 = -10.0
  LDG f
  LDG h
  MULF
  LDG h
  ADDF
  STG fprod2       ; 1.5 * 4.0 + 4.0 = 10.0
  RET
; expect end: finished
; expect sum2 = 44
; expect diff2 = 24
; expect fsum2 = 8.25
; expect fdiff2 = -10.0
; expect fprod2 = 10.0
