; a zero-extension of no bits
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 1
  ZEXT 0
  POP
  RET
; expect verify: BadOperand
