; the line-end mark (bit 8) on YIELD (opcode 0x60), which stops the slice before any line
; could end after it: only an instruction that runs on in the same slice may carry it
.routine function "main" in=0 out=0 entry=main
main:
  .word 0x00000160
  RET
; expect verify: BadLineEnd
