; Base code only (format 6), as it was written of the fused instructions named below before
; they left the stored format: the machine fuses it again at load (vm/fused.def), and the
; expectations are the same, so each fused handler is checked against its base code.
; The local-operand superinstructions, run directly. Locals: a = 7, b = 3 (int); x = 1.5,
; y = 4.0 (float); results in globals. RETEOL ends a line and returns from `half`.
.global int "ints" 5
.global float "floats" 6
.global int "moved" 1
.global float "fsum" 1
.global int "halved" 1
.const float 1.5
.const float 4.0
.routine function "main" in=0 out=0 entry=main
.local int "a"
.local int "b"
.local float "x"
.local float "y"
.local int "ri"
.local float "rf"
.routine function "half" in=1 out=1 entry=half
.local int "n"
.local int "h"
main:
  PUSHI 7
  STL 0
  PUSHI 3
  STL 1
  PUSHK 0
  STL 2
  PUSHK 1
  STL 3
  PUSHI 0
  LDL 0        ; a + b (locals 0 and 1)
  LDL 1
  ADDI
  STGX ints           ; ints[0] = 10
  PUSHI 1
  LDL 0        ; a - b
  LDL 1
  SUBI
  STGX ints           ; ints[1] = 4
  LDL 1         ; ri = b + a (pair 1|0<<16)
  LDL 0
  ADDI
  STL 4
  PUSHI 2
  LDL 4
  STGX ints           ; ints[2] = 10
  LDL 1         ; ri = b - a
  LDL 0
  SUBI
  STL 4
  PUSHI 3
  LDL 4
  STGX ints           ; ints[3] = -4
  PUSHI 0
  LDL 2       ; x + y (locals 2 and 3)
  LDL 3
  ADDF
  STGX floats         ; floats[0] = 5.5
  PUSHI 1
  LDL 2       ; x - y
  LDL 3
  SUBF
  STGX floats         ; floats[1] = -2.5
  PUSHI 2
  LDL 2       ; x * y
  LDL 3
  MULF
  STGX floats         ; floats[2] = 6
  LDL 3    ; rf = y + x (pair 3|2<<16)
  LDL 2
  ADDF
  STL 5
  PUSHI 3
  LDL 5
  STGX floats         ; floats[3] = 5.5
  LDL 3    ; rf = y - x
  LDL 2
  SUBF
  STL 5
  PUSHI 4
  LDL 5
  STGX floats         ; floats[4] = 2.5
  LDL 3    ; rf = y * x
  LDL 2
  MULF
  STL 5
  PUSHI 5
  LDL 5
  STGX floats         ; floats[5] = 6
  LDL 2            ; x, 4.0
  PUSHK 1
  MULF
  PUSHK 0            ; 1.5, y
  LDL 3
  ADDF
  ADDF
  STG fsum            ; x*4 + (1.5 + y) = 11.5
  LDL 0            ; ri = a
  STL 4
  LDL 4
  LDL 1
  SUBI
  STG moved           ; ri - b = 4
  PUSHI 4
  LDL 0
  STGX ints           ; ints[4] = a = 7
  PUSHI 9
  CALL half 1
  STG halved
  RET
half:
  LDL 0
  PUSHI 2
  DIVI
  STL 1
  RETEOL
; expect end: finished
; expect ints[0] = 10
; expect ints[1] = 4
; expect ints[2] = 10
; expect ints[3] = -4
; expect ints[4] = 7
; expect floats[0] = 5.5
; expect floats[1] = -2.5
; expect floats[2] = 6.0
; expect floats[3] = 5.5
; expect floats[4] = 2.5
; expect floats[5] = 6.0
; expect moved = 4
; expect fsum = 11.5
; expect halved = 4
