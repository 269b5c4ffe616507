; the first fused instruction's opcode (114, after BREAK's 113): the VM forms its fused
; instructions when it loads an image (vm/fused.def); an image holds base instructions only
.routine function "main" in=0 out=0 entry=main
main:
  .word 0x00000072
  RET
; expect verify: BadOpcode
