; an instruction whose second word is missing
.routine function "main" in=0 out=0 entry=main
main:
  RET
  .word 0x00000001
  .word 0x0000000c  ; INCL (opcode 12) needs a second word
; expect verify: Truncated
