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
  STGEOL x            ; x = 5, end of line
  PUSHI 7
  STG y
  STGK f 2            ; f = 1.5
  STGK h 3            ; h = 4.0
  STGK nan 4
  JEQGK t0 1          ; x == k0 (5) -> True
  JMP n0
t0:
  PUSHI 0
  PUSHI 1
  STGX taken
n0:
  JNEGK t1 65537      ; x != k1 (6) -> True
  JMP n1
t1:
  PUSHI 1
  PUSHI 1
  STGX taken
n1:
  JLTGK t2 65537      ; x < 6 -> True
  JMP n2
t2:
  PUSHI 2
  PUSHI 1
  STGX taken
n2:
  JLEGK t3 1          ; x <= 5 -> True
  JMP n3
t3:
  PUSHI 3
  PUSHI 1
  STGX taken
n3:
  JGTGK t4 1          ; x > 5 -> False
  JMP n4
t4:
  PUSHI 4
  PUSHI 1
  STGX taken
n4:
  JGEGK t5 65537      ; x >= 6 -> False
  JMP n5
t5:
  PUSHI 5
  PUSHI 1
  STGX taken
n5:
  JNEQFGK t6 131075   ; unless f == 1.5 -> False
  JMP n6
t6:
  PUSHI 6
  PUSHI 1
  STGX taken
n6:
  JNNEFGK t7 131075   ; unless f != 1.5 -> True
  JMP n7
t7:
  PUSHI 7
  PUSHI 1
  STGX taken
n7:
  JNLTFGK t8 196611   ; unless f < 4.0 -> False
  JMP n8
t8:
  PUSHI 8
  PUSHI 1
  STGX taken
n8:
  JNLEFGK t9 131075   ; unless f <= 1.5 -> False
  JMP n9
t9:
  PUSHI 9
  PUSHI 1
  STGX taken
n9:
  JNGTFGK t10 131075  ; unless f > 1.5 -> True
  JMP n10
t10:
  PUSHI 10
  PUSHI 1
  STGX taken
n10:
  JNGEFGK t11 196623  ; unless nan >= 4.0 (global 15, k3) -> True: NaN compares false
  JMP n11
t11:
  PUSHI 11
  PUSHI 1
  STGX taken
n11:
  JZG t12 1           ; x == 0 -> False
  JMP n12
t12:
  PUSHI 12
  PUSHI 1
  STGX taken
n12:
  JNZG t13 1          ; x != 0 -> True
  JMP n13
t13:
  PUSHI 13
  PUSHI 1
  STGX taken
n13:
  JZG t14 5           ; sum == 0 -> True
  JMP n14
t14:
  PUSHI 14
  PUSHI 1
  STGX taken
n14:
  ADDIGG 131073       ; x + y
  STG sum
  SUBIGG 65538        ; y - x
  STG diff
  ADDFGG 262147       ; f + h
  STG fsum
  SUBFGG 196612       ; h - f
  STG fdiff
  MULFGG 262147       ; f * h
  STG fprod
  ADDGK x -8          ; x - 8
  STG plus
  REMGK y -4          ; 7 % -4 (C's sign: the dividend's)
  STG rem
  INCG count 3
  INCG count -1       ; count = 2
  INCGEOL count 5     ; count = 7, end of line
  STGKEOL kept 3      ; kept = 4.0, end of line
  LDG2 x y
  SUBI
  STG pushed          ; x - y: LDG2 pushes x first
  PUSHI 42
  STGJEOL after 14    ; last = 42, end of line, jump over the store of 7
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
