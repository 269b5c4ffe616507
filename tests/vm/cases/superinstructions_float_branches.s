; Base code only (format 6), as it was written of the fused instructions named below before
; they left the stored format: the machine fuses it again at load (vm/fused.def), and the
; expectations are the same, so each fused handler is checked against its base code.
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
  LDL 0   ; x == y -> jumps
  LDL 1
  JNEQF t0
  JMP n0
t0:
  PUSHI 0
  PUSHI 1
  STGX taken
n0:
  LDL 0   ; x != y -> falls through
  LDL 1
  JNNEF t1
  JMP n1
t1:
  PUSHI 1
  PUSHI 1
  STGX taken
n1:
  LDL 0   ; x < y -> falls through
  LDL 1
  JNLTF t2
  JMP n2
t2:
  PUSHI 2
  PUSHI 1
  STGX taken
n2:
  LDL 0   ; x <= y -> falls through
  LDL 1
  JNLEF t3
  JMP n3
t3:
  PUSHI 3
  PUSHI 1
  STGX taken
n3:
  LDL 0   ; x > y -> jumps
  LDL 1
  JNGTF t4
  JMP n4
t4:
  PUSHI 4
  PUSHI 1
  STGX taken
n4:
  LDL 0   ; x >= y -> jumps
  LDL 1
  JNGEF t5
  JMP n5
t5:
  PUSHI 5
  PUSHI 1
  STGX taken
n5:
  LDL 0   ; x == 1.5 -> falls through
  PUSHK 0
  JNEQF t6
  JMP n6
t6:
  PUSHI 6
  PUSHI 1
  STGX taken
n6:
  LDL 0   ; x != 1.5 -> jumps
  PUSHK 0
  JNNEF t7
  JMP n7
t7:
  PUSHI 7
  PUSHI 1
  STGX taken
n7:
  LDL 0   ; x < 4.0 -> falls through
  PUSHK 1
  JNLTF t8
  JMP n8
t8:
  PUSHI 8
  PUSHI 1
  STGX taken
n8:
  LDL 0   ; x <= 1.5 -> falls through
  PUSHK 0
  JNLEF t9
  JMP n9
t9:
  PUSHI 9
  PUSHI 1
  STGX taken
n9:
  LDL 0   ; x > 4.0 -> jumps
  PUSHK 1
  JNGTF t10
  JMP n10
t10:
  PUSHI 10
  PUSHI 1
  STGX taken
n10:
  LDL 0   ; x >= 1.5 -> falls through
  PUSHK 0
  JNGEF t11
  JMP n11
t11:
  PUSHI 11
  PUSHI 1
  STGX taken
n11:
  LDL 2   ; q == q -> jumps
  LDL 2
  JNEQF t12
  JMP n12
t12:
  PUSHI 12
  PUSHI 1
  STGX taken
n12:
  LDL 2   ; q != x -> falls through
  LDL 0
  JNNEF t13
  JMP n13
t13:
  PUSHI 13
  PUSHI 1
  STGX taken
n13:
  LDL 2   ; q < 4.0 -> jumps
  PUSHK 1
  JNLTF t14
  JMP n14
t14:
  PUSHI 14
  PUSHI 1
  STGX taken
n14:
  LDL 0   ; x >= nan -> jumps
  PUSHK 2
  JNGEF t15
  JMP n15
t15:
  PUSHI 15
  PUSHI 1
  STGX taken
n15:
  LDL 0   ; x <= q -> jumps
  LDL 2
  JNLEF t16
  JMP n16
t16:
  PUSHI 16
  PUSHI 1
  STGX taken
n16:
  LDL 2   ; q > x -> jumps
  LDL 0
  JNGTF t17
  JMP n17
t17:
  PUSHI 17
  PUSHI 1
  STGX taken
n17:
  LDL 2   ; q != nan -> falls through
  PUSHK 2
  JNNEF t18
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
