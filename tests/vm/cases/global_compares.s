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
  JCMPGG t0 16385          ; lo == hi
  JMP n0
t0:
  PUSHI 0
  PUSHI 1
  STGX taken
n0:
  JCMPGG t1 16386          ; hi == hi
  JMP n1
t1:
  PUSHI 1
  PUSHI 1
  STGX taken
n1:
  JCMPGG t2 8194          ; hi == lo
  JMP n2
t2:
  PUSHI 2
  PUSHI 1
  STGX taken
n2:
  JCMPGG t3 8195          ; neg == lo
  JMP n3
t3:
  PUSHI 3
  PUSHI 1
  STGX taken
n3:
  JCMPGG t4 67125249          ; lo != hi
  JMP n4
t4:
  PUSHI 4
  PUSHI 1
  STGX taken
n4:
  JCMPGG t5 67125250          ; hi != hi
  JMP n5
t5:
  PUSHI 5
  PUSHI 1
  STGX taken
n5:
  JCMPGG t6 67117058          ; hi != lo
  JMP n6
t6:
  PUSHI 6
  PUSHI 1
  STGX taken
n6:
  JCMPGG t7 67117059          ; neg != lo
  JMP n7
t7:
  PUSHI 7
  PUSHI 1
  STGX taken
n7:
  JCMPGG t8 134234113          ; lo < hi
  JMP n8
t8:
  PUSHI 8
  PUSHI 1
  STGX taken
n8:
  JCMPGG t9 134234114          ; hi < hi
  JMP n9
t9:
  PUSHI 9
  PUSHI 1
  STGX taken
n9:
  JCMPGG t10 134225922          ; hi < lo
  JMP n10
t10:
  PUSHI 10
  PUSHI 1
  STGX taken
n10:
  JCMPGG t11 134225923          ; neg < lo
  JMP n11
t11:
  PUSHI 11
  PUSHI 1
  STGX taken
n11:
  JCMPGG t12 201342977          ; lo <= hi
  JMP n12
t12:
  PUSHI 12
  PUSHI 1
  STGX taken
n12:
  JCMPGG t13 201342978          ; hi <= hi
  JMP n13
t13:
  PUSHI 13
  PUSHI 1
  STGX taken
n13:
  JCMPGG t14 201334786          ; hi <= lo
  JMP n14
t14:
  PUSHI 14
  PUSHI 1
  STGX taken
n14:
  JCMPGG t15 201334787          ; neg <= lo
  JMP n15
t15:
  PUSHI 15
  PUSHI 1
  STGX taken
n15:
  JCMPGG t16 268451841          ; lo > hi
  JMP n16
t16:
  PUSHI 16
  PUSHI 1
  STGX taken
n16:
  JCMPGG t17 268451842          ; hi > hi
  JMP n17
t17:
  PUSHI 17
  PUSHI 1
  STGX taken
n17:
  JCMPGG t18 268443650          ; hi > lo
  JMP n18
t18:
  PUSHI 18
  PUSHI 1
  STGX taken
n18:
  JCMPGG t19 268443651          ; neg > lo
  JMP n19
t19:
  PUSHI 19
  PUSHI 1
  STGX taken
n19:
  JCMPGG t20 335560705          ; lo >= hi
  JMP n20
t20:
  PUSHI 20
  PUSHI 1
  STGX taken
n20:
  JCMPGG t21 335560706          ; hi >= hi
  JMP n21
t21:
  PUSHI 21
  PUSHI 1
  STGX taken
n21:
  JCMPGG t22 335552514          ; hi >= lo
  JMP n22
t22:
  PUSHI 22
  PUSHI 1
  STGX taken
n22:
  JCMPGG t23 335552515          ; neg >= lo
  JMP n23
t23:
  PUSHI 23
  PUSHI 1
  STGX taken
n23:
  JCMPGGEOL t24 134234113          ; lo < hi
  JMP n24
t24:
  PUSHI 24
  PUSHI 1
  STGX taken
n24:
  JCMPGGEOL t25 335560705          ; lo >= hi
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
