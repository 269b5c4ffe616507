; the first fused instruction's opcode (123, after BREAK's 122): the VM forms its fused
; instructions when it loads an image (vm/fused.def); an image holds base instructions only
.routine function "main" in=0 out=0 entry=main
main:
  .word 0x0000007b
  RET
; expect verify: BadOpcode
