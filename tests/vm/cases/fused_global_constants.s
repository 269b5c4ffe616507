; An int global compared with an int constant (a bound too large for an immediate: `while (i <=
; 30000000)`), and a loop's step on a global with its jump back: base code that the machine
; fuses at load into the six JxxGC and INCGJ (vm/fused.def). x = 5; k0 = 5, k1 = 6. taken[k] is
; 1 when test k jumps; the loop counts n to 3 in three turns.
.global int "taken" 6
.global int "x" 1
.global int "n" 1
.global int "turns" 1
.const int 5       ; k0
.const int 6       ; k1
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 5
  STG x
  LDG x
  PUSHK 0
  JEQI t0          ; 5 == 5: taken
  JMP n0
t0:
  PUSHI 0
  PUSHI 1
  STGX taken
n0:
  LDG x
  PUSHK 1
  JNEI t1          ; 5 != 6: taken
  JMP n1
t1:
  PUSHI 1
  PUSHI 1
  STGX taken
n1:
  LDG x
  PUSHK 0
  JLTI t2          ; 5 < 5: not
  JMP n2
t2:
  PUSHI 2
  PUSHI 1
  STGX taken
n2:
  LDG x
  PUSHK 0
  JLEI t3          ; 5 <= 5: taken
  JMP n3
t3:
  PUSHI 3
  PUSHI 1
  STGX taken
n3:
  LDG x
  PUSHK 1
  JGTI t4          ; 5 > 6: not
  JMP n4
t4:
  PUSHI 4
  PUSHI 1
  STGX taken
n4:
  LDG x
  PUSHK 1
  JGEI t5          ; 5 >= 6: not
  JMP n5
t5:
  PUSHI 5
  PUSHI 1
  STGX taken
n5:
top:
  LDG n
  PUSHI 3
  JGEI done
  LDG turns
  PUSHI 1
  ADDI
  STG turns
  LDG n
  PUSHI 1
  ADDI
  STG n
  JMP top          ; n = n + 1, and back
done:
  RET
; expect end: finished
; expect taken[0] = 1
; expect taken[1] = 1
; expect taken[2] = 0
; expect taken[3] = 1
; expect taken[4] = 0
; expect taken[5] = 0
; expect n = 3
; expect turns = 3
