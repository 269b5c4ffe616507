; A frame's words in the data memory (PDL's parameters, at a local's address plus an offset):
; base code that the machine fuses at load into STMLK (`n=5;`: the value, then the word's
; address and SWAP, STM), STEPMLK (`n++;`, `n--;`: the word plus 1 or -1, the compilers' form,
; or any immediate; times one stays base code), JRELMK for its six relations (`if (n < 5)` of a
; parameter) and an address's range tests, JULTK and the second alone as base code (a pointer
; into the user memory, or into a task's stack; both together are JULTKLK,
; fused_pointer_ranges.s). The data memory is the globals' words: `mem` is words 0..7, fp = 2,
; so fp + 1 is mem[3] and fp + 2 is mem[4].
; taken[k] is 1 when test k jumps.
.global int "mem" 8
.global int "taken" 6
.global int "in_range" 2
.routine function "main" in=0 out=0 entry=main
.local int "fp"
.local int "base"
main:
  PUSHI 2
  STL 0
  PUSHI 5
  STL 1
  PUSHI 5
  LDL 0
  PUSHI 1
  ADDI
  SWAP
  STM              ; mem[3] = 5 (STMLK)
  PUSHI -9
  LDL 0
  PUSHI 2
  ADDI
  SWAP
  STM              ; mem[4] = -9 (STMLK), and mem[3] stays
  LDL 0
  PUSHI 1
  ADDI
  LDM
  PUSHI 2
  ADDI
  LDL 0
  PUSHI 1
  ADDI
  SWAP
  STM              ; mem[3] = 5 + 2 = 7 (STEPMLK)
  LDL 0
  PUSHI 1
  ADDI
  LDM
  PUSHI -3
  ADDI
  LDL 0
  PUSHI 1
  ADDI
  SWAP
  STM              ; mem[3] = 7 + -3 = 4 (STEPMLK)
  PUSHI 6
  LDL 0
  PUSHI 3
  ADDI
  SWAP
  STM              ; mem[5] = 6
  LDL 0
  PUSHI 3
  ADDI
  LDM
  PUSHI 3
  MULI
  LDL 0
  PUSHI 3
  ADDI
  SWAP
  STM              ; mem[5] = 6 * 3 = 18 (base code: a step adds)
  LDL 0
  PUSHI 1
  ADDI
  LDM
  PUSHI 4
  JEQI t0          ; 4 == 4: taken
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
  PUSHI 4
  JNEI t1          ; 4 != 4: not
  JMP n1
t1:
  PUSHI 1
  PUSHI 1
  STGX taken
n1:
  LDL 0
  PUSHI 1
  ADDI
  LDM
  PUSHI 5
  JLTI t2          ; 4 < 5: taken
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
  PUSHI 3
  JLEI t3          ; 4 <= 3: not
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
  PUSHI 3
  JGTI t4          ; 4 > 3: taken
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
  PUSHI 5
  JGEI t5          ; 4 >= 5: not
  JMP n5
t5:
  PUSHI 5
  PUSHI 1
  STGX taken
n5:
  LDL 0
  DUP
  PUSHI 8
  CMPU 2
  JNZ r0           ; 2 < 8 (unsigned): taken
  POP
  JMP n6
r0:
  POP
  PUSHI 0
  PUSHI 1
  STGX in_range
n6:
  LDL 0
  DUP
  LDL 1
  SUBI
  PUSHI 4
  CMPU 2
  JNZ r1           ; 2 - 5 (a wrapped 2^32 - 3) < 4 (unsigned): not
  POP
  JMP n7
r1:
  POP
  PUSHI 1
  PUSHI 1
  STGX in_range
n7:
  RET
; expect end: finished
; expect mem[3] = 4
; expect mem[4] = -9
; expect mem[5] = 18
; expect taken[0] = 1
; expect taken[1] = 0
; expect taken[2] = 1
; expect taken[3] = 0
; expect taken[4] = 1
; expect taken[5] = 0
; expect in_range[0] = 1
; expect in_range[1] = 0
