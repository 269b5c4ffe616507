; an unsigned comparison with no such relation
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 1
  PUSHI 2
  CMPU 6
  POP
  RET
; expect verify: BadOperand
