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
  ADDILL 65536        ; a + b (locals 0 and 1)
  STGX ints           ; ints[0] = 10
  PUSHI 1
  SUBILL 65536        ; a - b
  STGX ints           ; ints[1] = 4
  ADDILLS 4 1         ; ri = b + a (pair 1|0<<16)
  PUSHI 2
  LDL 4
  STGX ints           ; ints[2] = 10
  SUBILLS 4 1         ; ri = b - a
  PUSHI 3
  LDL 4
  STGX ints           ; ints[3] = -4
  PUSHI 0
  ADDFLL 196610       ; x + y (locals 2 and 3)
  STGX floats         ; floats[0] = 5.5
  PUSHI 1
  SUBFLL 196610       ; x - y
  STGX floats         ; floats[1] = -2.5
  PUSHI 2
  MULFLL 196610       ; x * y
  STGX floats         ; floats[2] = 6
  ADDFLLS 5 131075    ; rf = y + x (pair 3|2<<16)
  PUSHI 3
  LDL 5
  STGX floats         ; floats[3] = 5.5
  SUBFLLS 5 131075    ; rf = y - x
  PUSHI 4
  LDL 5
  STGX floats         ; floats[4] = 2.5
  MULFLLS 5 131075    ; rf = y * x
  PUSHI 5
  LDL 5
  STGX floats         ; floats[5] = 6
  LDLK 2 1            ; x, 4.0
  MULF
  LDKL 0 3            ; 1.5, y
  ADDF
  ADDF
  STG fsum            ; x*4 + (1.5 + y) = 11.5
  MOVL 4 0            ; ri = a
  LDL2 4 1
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
