; Base code only (format 6), as it was written of the fused instructions named below before
; they left the stored format: the machine fuses it again at load (vm/fused.def), and the
; expectations are the same, so each fused handler is checked against its base code.
; The superinstructions on globals, each run directly. taken[k] is 1 when test k jumps (the
; comments give each test and its answer); x = 5, y = 7 (int), f = 1.5, h = 4.0 (float).
; Packed operands: a global in bits 0..15, the second global or a constant's index in 16..31.
.global int "taken" 20
.global int "x" 1
.global int "y" 1
.global float "f" 1
.global float "h" 1
.global int "sum" 1
.global int "diff" 1
.global float "fsum" 1
.global float "fdiff" 1
.global float "fprod" 1
.global int "plus" 1
.global int "rem" 1
.global int "count" 1
.global int "pushed" 1
.global int "last" 1
.global float "nan" 1
.global float "kept" 1
.const int 5       ; k0
.const int 6       ; k1
.const float 1.5   ; k2
.const float 4.0   ; k3
.const float bits 0x7fc00000   ; k4, a NaN
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 5
  STG.eol x            ; x = 5, end of line
  PUSHI 7
  STG y
  PUSHK 2            ; f = 1.5
  STG f
  PUSHK 3            ; h = 4.0
  STG h
  PUSHK 4
  STG nan
  LDG 1          ; x == k0 (5) -> True
  PUSHI 5
  JEQI t0
  JMP n0
t0:
  PUSHI 0
  PUSHI 1
  STGX taken
n0:
  LDG 1      ; x != k1 (6) -> True
  PUSHI 6
  JNEI t1
  JMP n1
t1:
  PUSHI 1
  PUSHI 1
  STGX taken
n1:
  LDG 1      ; x < 6 -> True
  PUSHI 6
  JLTI t2
  JMP n2
t2:
  PUSHI 2
  PUSHI 1
  STGX taken
n2:
  LDG 1          ; x <= 5 -> True
  PUSHI 5
  JLEI t3
  JMP n3
t3:
  PUSHI 3
  PUSHI 1
  STGX taken
n3:
  LDG 1          ; x > 5 -> False
  PUSHI 5
  JGTI t4
  JMP n4
t4:
  PUSHI 4
  PUSHI 1
  STGX taken
n4:
  LDG 1      ; x >= 6 -> False
  PUSHI 6
  JGEI t5
  JMP n5
t5:
  PUSHI 5
  PUSHI 1
  STGX taken
n5:
  LDG 3   ; unless f == 1.5 -> False
  PUSHK 2
  JNEQF t6
  JMP n6
t6:
  PUSHI 6
  PUSHI 1
  STGX taken
n6:
  LDG 3   ; unless f != 1.5 -> True
  PUSHK 2
  JNNEF t7
  JMP n7
t7:
  PUSHI 7
  PUSHI 1
  STGX taken
n7:
  LDG 3   ; unless f < 4.0 -> False
  PUSHK 3
  JNLTF t8
  JMP n8
t8:
  PUSHI 8
  PUSHI 1
  STGX taken
n8:
  LDG 3   ; unless f <= 1.5 -> False
  PUSHK 2
  JNLEF t9
  JMP n9
t9:
  PUSHI 9
  PUSHI 1
  STGX taken
n9:
  LDG 3  ; unless f > 1.5 -> True
  PUSHK 2
  JNGTF t10
  JMP n10
t10:
  PUSHI 10
  PUSHI 1
  STGX taken
n10:
  LDG 15  ; unless nan >= 4.0 (global 15, k3) -> True: NaN compares false
  PUSHK 3
  JNGEF t11
  JMP n11
t11:
  PUSHI 11
  PUSHI 1
  STGX taken
n11:
  LDG 1           ; x == 0 -> False
  JZ t12
  JMP n12
t12:
  PUSHI 12
  PUSHI 1
  STGX taken
n12:
  LDG 1          ; x != 0 -> True
  JNZ t13
  JMP n13
t13:
  PUSHI 13
  PUSHI 1
  STGX taken
n13:
  LDG 5           ; sum == 0 -> True
  JZ t14
  JMP n14
t14:
  PUSHI 14
  PUSHI 1
  STGX taken
n14:
  LDG 1       ; x + y
  LDG 2
  ADDI
  STG sum
  LDG 2        ; y - x
  LDG 1
  SUBI
  STG diff
  LDG 3       ; f + h
  LDG 4
  ADDF
  STG fsum
  LDG 4       ; h - f
  LDG 3
  SUBF
  STG fdiff
  LDG 3       ; f * h
  LDG 4
  MULF
  STG fprod
  LDG x          ; x - 8
  PUSHI -8
  ADDI
  STG plus
  LDG y          ; 7 % -4 (C's sign: the dividend's)
  PUSHI -4
  REMI
  STG rem
  LDG count
  PUSHI 3
  ADDI
  STG count
  LDG count       ; count = 2
  PUSHI -1
  ADDI
  STG count
  LDG count     ; count = 7, end of line
  PUSHI 5
  ADDI
  STG.eol count
  PUSHK 3      ; kept = 4.0, end of line
  STG.eol kept
  LDG x
  LDG y
  SUBI
  STG pushed          ; x - y: LDG2 pushes x first
  PUSHI 42
  STG 14    ; last = 42, end of line, jump over the store of 7
  JMP.eol after
  PUSHI 7
  STG last
after:
  RET
; expect end: finished
; expect x = 5
; expect f = 1.5
; expect h = 4.0
; expect taken[0] = 1
; expect taken[1] = 1
; expect taken[2] = 1
; expect taken[3] = 1
; expect taken[4] = 0
; expect taken[5] = 0
; expect taken[6] = 0
; expect taken[7] = 1
; expect taken[8] = 0
; expect taken[9] = 0
; expect taken[10] = 1
; expect taken[11] = 1
; expect taken[12] = 0
; expect taken[13] = 1
; expect taken[14] = 1
; expect sum = 12
; expect diff = 2
; expect fsum = 5.5
; expect fdiff = 2.5
; expect fprod = 6.0
; expect plus = -3
; expect rem = 3
; expect count = 7
; expect kept = 4.0
; expect pushed = -2
; expect last = 42
