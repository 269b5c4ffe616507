; Base code only (format 6), as it was written of the fused instructions named below before
; they left the stored format: the machine fuses it again at load (vm/fused.def), and the
; expectations are the same, so each fused handler is checked against its base code.
; JCMPGG and JCMPGGEOL: two int globals compared, the comparison packed with them in B
; (the first global in bits 0..12, the second in 13..25, the comparison 0..5 for == != < <=
; > >= in 26..28). taken[k] is 1 when test k jumps; lo = 3, hi = 9, neg = -4 (signed).
; Where JCMPGGEOL's line ends is the peephole test's; here, where it goes.
.global int "taken" 26
.global int "lo" 1
.global int "hi" 1
.global int "neg" 1
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 3
  STG lo
  PUSHI 9
  STG hi
  PUSHI -4
  STG neg
  LDG 1          ; lo == hi
  LDG 2
  JEQI t0
  JMP n0
t0:
  PUSHI 0
  PUSHI 1
  STGX taken
n0:
  LDG 2          ; hi == hi
  LDG 2
  JEQI t1
  JMP n1
t1:
  PUSHI 1
  PUSHI 1
  STGX taken
n1:
  LDG 2          ; hi == lo
  LDG 1
  JEQI t2
  JMP n2
t2:
  PUSHI 2
  PUSHI 1
  STGX taken
n2:
  LDG 3          ; neg == lo
  LDG 1
  JEQI t3
  JMP n3
t3:
  PUSHI 3
  PUSHI 1
  STGX taken
n3:
  LDG 1          ; lo != hi
  LDG 2
  JNEI t4
  JMP n4
t4:
  PUSHI 4
  PUSHI 1
  STGX taken
n4:
  LDG 2          ; hi != hi
  LDG 2
  JNEI t5
  JMP n5
t5:
  PUSHI 5
  PUSHI 1
  STGX taken
n5:
  LDG 2          ; hi != lo
  LDG 1
  JNEI t6
  JMP n6
t6:
  PUSHI 6
  PUSHI 1
  STGX taken
n6:
  LDG 3          ; neg != lo
  LDG 1
  JNEI t7
  JMP n7
t7:
  PUSHI 7
  PUSHI 1
  STGX taken
n7:
  LDG 1          ; lo < hi
  LDG 2
  JLTI t8
  JMP n8
t8:
  PUSHI 8
  PUSHI 1
  STGX taken
n8:
  LDG 2          ; hi < hi
  LDG 2
  JLTI t9
  JMP n9
t9:
  PUSHI 9
  PUSHI 1
  STGX taken
n9:
  LDG 2          ; hi < lo
  LDG 1
  JLTI t10
  JMP n10
t10:
  PUSHI 10
  PUSHI 1
  STGX taken
n10:
  LDG 3          ; neg < lo
  LDG 1
  JLTI t11
  JMP n11
t11:
  PUSHI 11
  PUSHI 1
  STGX taken
n11:
  LDG 1          ; lo <= hi
  LDG 2
  JLEI t12
  JMP n12
t12:
  PUSHI 12
  PUSHI 1
  STGX taken
n12:
  LDG 2          ; hi <= hi
  LDG 2
  JLEI t13
  JMP n13
t13:
  PUSHI 13
  PUSHI 1
  STGX taken
n13:
  LDG 2          ; hi <= lo
  LDG 1
  JLEI t14
  JMP n14
t14:
  PUSHI 14
  PUSHI 1
  STGX taken
n14:
  LDG 3          ; neg <= lo
  LDG 1
  JLEI t15
  JMP n15
t15:
  PUSHI 15
  PUSHI 1
  STGX taken
n15:
  LDG 1          ; lo > hi
  LDG 2
  JGTI t16
  JMP n16
t16:
  PUSHI 16
  PUSHI 1
  STGX taken
n16:
  LDG 2          ; hi > hi
  LDG 2
  JGTI t17
  JMP n17
t17:
  PUSHI 17
  PUSHI 1
  STGX taken
n17:
  LDG 2          ; hi > lo
  LDG 1
  JGTI t18
  JMP n18
t18:
  PUSHI 18
  PUSHI 1
  STGX taken
n18:
  LDG 3          ; neg > lo
  LDG 1
  JGTI t19
  JMP n19
t19:
  PUSHI 19
  PUSHI 1
  STGX taken
n19:
  LDG 1          ; lo >= hi
  LDG 2
  JGEI t20
  JMP n20
t20:
  PUSHI 20
  PUSHI 1
  STGX taken
n20:
  LDG 2          ; hi >= hi
  LDG 2
  JGEI t21
  JMP n21
t21:
  PUSHI 21
  PUSHI 1
  STGX taken
n21:
  LDG 2          ; hi >= lo
  LDG 1
  JGEI t22
  JMP n22
t22:
  PUSHI 22
  PUSHI 1
  STGX taken
n22:
  LDG 3          ; neg >= lo
  LDG 1
  JGEI t23
  JMP n23
t23:
  PUSHI 23
  PUSHI 1
  STGX taken
n23:
  LDG 1          ; lo < hi
  LDG 2
  JLTI.eol t24
  JMP n24
t24:
  PUSHI 24
  PUSHI 1
  STGX taken
n24:
  LDG 1          ; lo >= hi
  LDG 2
  JGEI.eol t25
  JMP n25
t25:
  PUSHI 25
  PUSHI 1
  STGX taken
n25:
  RET
; expect end: finished
; expect taken[0] = 0
; expect taken[1] = 1
; expect taken[2] = 0
; expect taken[3] = 0
; expect taken[4] = 1
; expect taken[5] = 0
; expect taken[6] = 1
; expect taken[7] = 1
; expect taken[8] = 1
; expect taken[9] = 0
; expect taken[10] = 0
; expect taken[11] = 1
; expect taken[12] = 1
; expect taken[13] = 1
; expect taken[14] = 0
; expect taken[15] = 1
; expect taken[16] = 0
; expect taken[17] = 0
; expect taken[18] = 1
; expect taken[19] = 0
; expect taken[20] = 0
; expect taken[21] = 1
; expect taken[22] = 1
; expect taken[23] = 0
; expect taken[24] = 1
; expect taken[25] = 0
