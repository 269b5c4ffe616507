; an opcode number that is no base instruction (255: 0..112 are the base set, 113 BREAK, and
; the VM numbers its fused instructions after it)
.routine function "main" in=0 out=0 entry=main
main:
  .word 0x000000ff
  RET
; expect verify: BadOpcode
