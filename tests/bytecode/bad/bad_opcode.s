; an opcode number that does not exist (255: 0..252 are taken)
.routine function "main" in=0 out=0 entry=main
main:
  .word 0x000000ff
  RET
; expect verify: BadOpcode
