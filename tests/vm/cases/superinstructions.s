; Base code only (format 6), as it was written of the fused instructions named below before
; they left the stored format: the machine fuses it again at load (vm/fused.def), and the
; expectations are the same, so each fused handler is checked against its base code.
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
  LDL 0   ; JEQLL x y -> False
  LDL 1
  JEQI t0
  JMP n0
t0:
  PUSHI 0
  PUSHI 1
  STGX taken
n0:
  LDL 0   ; JNELL x y -> True
  LDL 1
  JNEI t1
  JMP n1
t1:
  PUSHI 1
  PUSHI 1
  STGX taken
n1:
  LDL 0   ; JLTLL x y -> True
  LDL 1
  JLTI t2
  JMP n2
t2:
  PUSHI 2
  PUSHI 1
  STGX taken
n2:
  LDL 0   ; JLELL x y -> True
  LDL 1
  JLEI t3
  JMP n3
t3:
  PUSHI 3
  PUSHI 1
  STGX taken
n3:
  LDL 0   ; JGTLL x y -> False
  LDL 1
  JGTI t4
  JMP n4
t4:
  PUSHI 4
  PUSHI 1
  STGX taken
n4:
  LDL 0   ; JGELL x y -> False
  LDL 1
  JGEI t5
  JMP n5
t5:
  PUSHI 5
  PUSHI 1
  STGX taken
n5:
  LDL 0   ; JEQLK x 5 -> True
  PUSHI 5
  JEQI t6
  JMP n6
t6:
  PUSHI 6
  PUSHI 1
  STGX taken
n6:
  LDL 0   ; JNELK x 5 -> False
  PUSHI 5
  JNEI t7
  JMP n7
t7:
  PUSHI 7
  PUSHI 1
  STGX taken
n7:
  LDL 0   ; JLTLK x 6 -> True
  PUSHI 6
  JLTI t8
  JMP n8
t8:
  PUSHI 8
  PUSHI 1
  STGX taken
n8:
  LDL 0   ; JLELK x 4 -> False
  PUSHI 4
  JLEI t9
  JMP n9
t9:
  PUSHI 9
  PUSHI 1
  STGX taken
n9:
  LDL 0   ; JGTLK x -3 -> True
  PUSHI -3
  JGTI t10
  JMP n10
t10:
  PUSHI 10
  PUSHI 1
  STGX taken
n10:
  LDL 0   ; JGELK x 5 -> True
  PUSHI 5
  JGEI t11
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
  LDL 1
  PUSHI -10
  ADDI
  STG sum            ; y - 10 = -3
  LDL 1
  PUSHI 4
  REMI
  STG rem            ; 7 % 4 = 3
count:
  LDG lines
  PUSHI 1
  ADDI
  STG lines
  LDG lines
  PUSHI 3
  JGEI out
  JMP.eol count      ; a line end that also loops
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
