; The superinstructions the peephole pass makes, each run directly. Locals: x = 5, y = 7.
; taken[k] is 1 when test k jumps (the comments give each test and its answer).
.global int "taken" 24
.global int "sum" 1
.global int "rem" 1
.global int "lines" 1
.const float 1.0
.const float 2.0
.routine function "main" in=0 out=0 entry=main
.local int "x"
.local int "y"
main:
  PUSHI 5
  STL 0
  PUSHI 7
  STL 1
  JEQLL t0 65536   ; JEQLL x y -> False
  JMP n0
t0:
  PUSHI 0
  PUSHI 1
  STGX taken
n0:
  JNELL t1 65536   ; JNELL x y -> True
  JMP n1
t1:
  PUSHI 1
  PUSHI 1
  STGX taken
n1:
  JLTLL t2 65536   ; JLTLL x y -> True
  JMP n2
t2:
  PUSHI 2
  PUSHI 1
  STGX taken
n2:
  JLELL t3 65536   ; JLELL x y -> True
  JMP n3
t3:
  PUSHI 3
  PUSHI 1
  STGX taken
n3:
  JGTLL t4 65536   ; JGTLL x y -> False
  JMP n4
t4:
  PUSHI 4
  PUSHI 1
  STGX taken
n4:
  JGELL t5 65536   ; JGELL x y -> False
  JMP n5
t5:
  PUSHI 5
  PUSHI 1
  STGX taken
n5:
  JEQLK t6 327680   ; JEQLK x 5 -> True
  JMP n6
t6:
  PUSHI 6
  PUSHI 1
  STGX taken
n6:
  JNELK t7 327680   ; JNELK x 5 -> False
  JMP n7
t7:
  PUSHI 7
  PUSHI 1
  STGX taken
n7:
  JLTLK t8 393216   ; JLTLK x 6 -> True
  JMP n8
t8:
  PUSHI 8
  PUSHI 1
  STGX taken
n8:
  JLELK t9 262144   ; JLELK x 4 -> False
  JMP n9
t9:
  PUSHI 9
  PUSHI 1
  STGX taken
n9:
  JGTLK t10 4294770688   ; JGTLK x -3 -> True
  JMP n10
t10:
  PUSHI 10
  PUSHI 1
  STGX taken
n10:
  JGELK t11 327680   ; JGELK x 5 -> True
  JMP n11
t11:
  PUSHI 11
  PUSHI 1
  STGX taken
n11:
  PUSHI 3
  PUSHI 3
  JEQI t12   ; 3 vs 3 -> True
  JMP n12
t12:
  PUSHI 12
  PUSHI 1
  STGX taken
n12:
  PUSHI 3
  PUSHI 3
  JNEI t13   ; 3 vs 3 -> False
  JMP n13
t13:
  PUSHI 13
  PUSHI 1
  STGX taken
n13:
  PUSHI 2
  PUSHI 3
  JLTI t14   ; 2 vs 3 -> True
  JMP n14
t14:
  PUSHI 14
  PUSHI 1
  STGX taken
n14:
  PUSHI 4
  PUSHI 3
  JLEI t15   ; 4 vs 3 -> False
  JMP n15
t15:
  PUSHI 15
  PUSHI 1
  STGX taken
n15:
  PUSHI 4
  PUSHI 3
  JGTI t16   ; 4 vs 3 -> True
  JMP n16
t16:
  PUSHI 16
  PUSHI 1
  STGX taken
n16:
  PUSHI 2
  PUSHI 3
  JGEI t17   ; 2 vs 3 -> False
  JMP n17
t17:
  PUSHI 17
  PUSHI 1
  STGX taken
n17:
  PUSHK 0
  PUSHK 1
  JNEQF t18   ; -> True
  JMP n18
t18:
  PUSHI 18
  PUSHI 1
  STGX taken
n18:
  PUSHK 0
  PUSHK 1
  JNNEF t19   ; -> False
  JMP n19
t19:
  PUSHI 19
  PUSHI 1
  STGX taken
n19:
  PUSHK 0
  PUSHK 1
  JNLTF t20   ; -> False
  JMP n20
t20:
  PUSHI 20
  PUSHI 1
  STGX taken
n20:
  PUSHK 1
  PUSHK 0
  JNLEF t21   ; -> True
  JMP n21
t21:
  PUSHI 21
  PUSHI 1
  STGX taken
n21:
  PUSHK 0
  PUSHK 1
  JNGTF t22   ; -> True
  JMP n22
t22:
  PUSHI 22
  PUSHI 1
  STGX taken
n22:
  PUSHK 1
  PUSHK 0
  JNGEF t23   ; -> False
  JMP n23
t23:
  PUSHI 23
  PUSHI 1
  STGX taken
n23:
  ADDLK 1 -10
  STG sum            ; y - 10 = -3
  REMLK 1 4
  STG rem            ; 7 % 4 = 3
count:
  LDG lines
  PUSHI 1
  ADDI
  STG lines
  LDG lines
  PUSHI 3
  JGEI out
  JMPEOL count      ; a line end that also loops
out:
  RET
; expect end: finished
; expect taken[0] = 0
; expect taken[1] = 1
; expect taken[2] = 1
; expect taken[3] = 1
; expect taken[4] = 0
; expect taken[5] = 0
; expect taken[6] = 1
; expect taken[7] = 0
; expect taken[8] = 1
; expect taken[9] = 0
; expect taken[10] = 1
; expect taken[11] = 1
; expect taken[12] = 1
; expect taken[13] = 0
; expect taken[14] = 1
; expect taken[15] = 0
; expect taken[16] = 1
; expect taken[17] = 0
; expect taken[18] = 1
; expect taken[19] = 0
; expect taken[20] = 0
; expect taken[21] = 1
; expect taken[22] = 1
; expect taken[23] = 0
; expect sum = -3
; expect rem = 3
; expect lines = 3
