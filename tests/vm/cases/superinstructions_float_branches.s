; The fused float compare-and-branch superinstructions on locals and constants, run directly.
; Each jumps *unless* its comparison holds, so a NaN operand always jumps except for !=.
; Locals: x = 1.5, y = 4.0, q = NaN; constants k0 = 1.5, k1 = 4.0, k2 = NaN. taken[k] is
; 1 when test k jumps (the comments give each comparison).
.global int "taken" 19
.const float 1.5
.const float 4.0
.const float bits 2143289344   ; a quiet NaN
.routine function "main" in=0 out=0 entry=main
.local float "x"
.local float "y"
.local float "q"
main:
  PUSHK 0
  STL 0
  PUSHK 1
  STL 1
  PUSHK 2
  STL 2
  JNEQFLL t0 65536   ; x == y -> jumps
  JMP n0
t0:
  PUSHI 0
  PUSHI 1
  STGX taken
n0:
  JNNEFLL t1 65536   ; x != y -> falls through
  JMP n1
t1:
  PUSHI 1
  PUSHI 1
  STGX taken
n1:
  JNLTFLL t2 65536   ; x < y -> falls through
  JMP n2
t2:
  PUSHI 2
  PUSHI 1
  STGX taken
n2:
  JNLEFLL t3 65536   ; x <= y -> falls through
  JMP n3
t3:
  PUSHI 3
  PUSHI 1
  STGX taken
n3:
  JNGTFLL t4 65536   ; x > y -> jumps
  JMP n4
t4:
  PUSHI 4
  PUSHI 1
  STGX taken
n4:
  JNGEFLL t5 65536   ; x >= y -> jumps
  JMP n5
t5:
  PUSHI 5
  PUSHI 1
  STGX taken
n5:
  JNEQFLK t6 0   ; x == 1.5 -> falls through
  JMP n6
t6:
  PUSHI 6
  PUSHI 1
  STGX taken
n6:
  JNNEFLK t7 0   ; x != 1.5 -> jumps
  JMP n7
t7:
  PUSHI 7
  PUSHI 1
  STGX taken
n7:
  JNLTFLK t8 65536   ; x < 4.0 -> falls through
  JMP n8
t8:
  PUSHI 8
  PUSHI 1
  STGX taken
n8:
  JNLEFLK t9 0   ; x <= 1.5 -> falls through
  JMP n9
t9:
  PUSHI 9
  PUSHI 1
  STGX taken
n9:
  JNGTFLK t10 65536   ; x > 4.0 -> jumps
  JMP n10
t10:
  PUSHI 10
  PUSHI 1
  STGX taken
n10:
  JNGEFLK t11 0   ; x >= 1.5 -> falls through
  JMP n11
t11:
  PUSHI 11
  PUSHI 1
  STGX taken
n11:
  JNEQFLL t12 131074   ; q == q -> jumps
  JMP n12
t12:
  PUSHI 12
  PUSHI 1
  STGX taken
n12:
  JNNEFLL t13 2   ; q != x -> falls through
  JMP n13
t13:
  PUSHI 13
  PUSHI 1
  STGX taken
n13:
  JNLTFLK t14 65538   ; q < 4.0 -> jumps
  JMP n14
t14:
  PUSHI 14
  PUSHI 1
  STGX taken
n14:
  JNGEFLK t15 131072   ; x >= nan -> jumps
  JMP n15
t15:
  PUSHI 15
  PUSHI 1
  STGX taken
n15:
  JNLEFLL t16 131072   ; x <= q -> jumps
  JMP n16
t16:
  PUSHI 16
  PUSHI 1
  STGX taken
n16:
  JNGTFLL t17 2   ; q > x -> jumps
  JMP n17
t17:
  PUSHI 17
  PUSHI 1
  STGX taken
n17:
  JNNEFLK t18 131074   ; q != nan -> falls through
  JMP n18
t18:
  PUSHI 18
  PUSHI 1
  STGX taken
n18:
  RET
; expect end: finished
; expect taken[0] = 1
; expect taken[1] = 0
; expect taken[2] = 0
; expect taken[3] = 0
; expect taken[4] = 1
; expect taken[5] = 1
; expect taken[6] = 0
; expect taken[7] = 1
; expect taken[8] = 0
; expect taken[9] = 0
; expect taken[10] = 1
; expect taken[11] = 0
; expect taken[12] = 1
; expect taken[13] = 0
; expect taken[14] = 1
; expect taken[15] = 1
; expect taken[16] = 1
; expect taken[17] = 1
; expect taken[18] = 0
