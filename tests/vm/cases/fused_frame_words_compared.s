; Two words of a frame in the data memory compared (a PDL procedure's `while (i < n)` of its
; variables): base code that the machine fuses at load into JRELMM, the relation read from the
; jump. The data memory is the globals' words: `mem` is words 0..7, fp = 2, so fp + 1 is mem[3]
; (4) and fp + 2 is mem[4] (7). taken[k] is 1 when test k jumps: 4 < 7, not 4 >= 7, 7 == 7, not
; 4 > 7, 4 != 7, 4 <= 4, not 7 <= 4.
.global int "mem" 8
.global int "taken" 7
.routine function "main" in=0 out=0 entry=main
.local int "fp"
main:
  PUSHI 2
  STL 0
  PUSHI 4
  LDL 0
  PUSHI 1
  ADDI
  SWAP
  STM              ; mem[3] = 4
  PUSHI 7
  LDL 0
  PUSHI 2
  ADDI
  SWAP
  STM              ; mem[4] = 7
  LDL 0
  PUSHI 1
  ADDI
  LDM
  LDL 0
  PUSHI 2
  ADDI
  LDM
  JLTI t0          ; 4 < 7
  JMP n0
t0:
  PUSHI 0
  PUSHI 1
  STGX taken
n0:
  LDL 0
  PUSHI 1
  ADDI
  LDM
  LDL 0
  PUSHI 2
  ADDI
  LDM
  JGEI t1          ; 4 >= 7
  JMP n1
t1:
  PUSHI 1
  PUSHI 1
  STGX taken
n1:
  LDL 0
  PUSHI 2
  ADDI
  LDM
  LDL 0
  PUSHI 2
  ADDI
  LDM
  JEQI t2          ; 7 == 7
  JMP n2
t2:
  PUSHI 2
  PUSHI 1
  STGX taken
n2:
  LDL 0
  PUSHI 1
  ADDI
  LDM
  LDL 0
  PUSHI 2
  ADDI
  LDM
  JGTI t3          ; 4 > 7
  JMP n3
t3:
  PUSHI 3
  PUSHI 1
  STGX taken
n3:
  LDL 0
  PUSHI 1
  ADDI
  LDM
  LDL 0
  PUSHI 2
  ADDI
  LDM
  JNEI t4          ; 4 != 7
  JMP n4
t4:
  PUSHI 4
  PUSHI 1
  STGX taken
n4:
  LDL 0
  PUSHI 1
  ADDI
  LDM
  LDL 0
  PUSHI 1
  ADDI
  LDM
  JLEI t5          ; 4 <= 4
  JMP n5
t5:
  PUSHI 5
  PUSHI 1
  STGX taken
n5:
  LDL 0
  PUSHI 2
  ADDI
  LDM
  LDL 0
  PUSHI 1
  ADDI
  LDM
  JLEI t6          ; 7 <= 4
  JMP n6
t6:
  PUSHI 6
  PUSHI 1
  STGX taken
n6:
  RET
; expect end: finished
; expect taken[0] = 1
; expect taken[1] = 0
; expect taken[2] = 1
; expect taken[3] = 0
; expect taken[4] = 1
; expect taken[5] = 1
; expect taken[6] = 0
