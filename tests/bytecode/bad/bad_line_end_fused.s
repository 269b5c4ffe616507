; the line-end mark (bit 8) on MULIK 7 (opcode 0xf7), a superinstruction, whose dispatch
; does not look for it
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 3
  .word 0x00000ff7
  POP
  RET
; expect verify: BadLineEnd
