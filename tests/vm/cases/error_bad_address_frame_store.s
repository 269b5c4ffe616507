; Run-time error BadAddress from a frame word's store (STMLK, fused at load: the value, the
; word's address, SWAP and STM): fp = 2 plus 1 is mem[3] and is stored; fp + 7 = 9 is one
; past the data memory's 9 words (mem, then last at 8), so the second store stores nothing and
; `last` keeps 7.
.global int "mem" 8
.global int "last" 1
.routine function "main" in=0 out=0 entry=main
.local int "fp"
main:
  PUSHI 2
  STL 0
  PUSHI 7
  STG last
  PUSHI 11
  LDL 0
  PUSHI 1
  ADDI
  SWAP
  STM
  PUSHI 13
  LDL 0
  PUSHI 7
  ADDI
  SWAP
  STM
  RET
; expect end: error BadAddress
; expect mem[3] = 11
; expect last = 7
