; A frame statement's fused form (OPIMLS) with its result's word outside the data memory (here
; 8 words; fp + 20): BadAddress, as the base code's STM raises it, and nothing is stored. Its
; operands' words are inside: mem[3] + mem[4] would be 42.
.global int "mem" 8
.global int "after" 1
.routine function "main" in=0 out=0 entry=main
.local int "fp"
main:
  PUSHI 2
  STL 0
  PUSHI 40
  LDL 0
  PUSHI 1
  ADDI
  SWAP
  STM              ; mem[3] = 40
  PUSHI 2
  LDL 0
  PUSHI 2
  ADDI
  SWAP
  STM              ; mem[4] = 2
  LDL 0
  PUSHI 1
  ADDI
  LDM
  LDL 0
  PUSHI 2
  ADDI
  LDM
  ADDI
  LDL 0
  PUSHI 20
  ADDI
  SWAP
  STM             ; word 22: outside
  PUSHI 1
  STG after
  RET
; expect end: error BadAddress
; expect mem[3] = 40
; expect mem[4] = 2
; expect after = 0
