; an opcode number that does not exist
.routine function "main" in=0 out=0 entry=main
main:
  .word 0x000000fe
  RET
; expect verify: BadOpcode
