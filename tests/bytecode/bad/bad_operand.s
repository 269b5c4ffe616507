; a call that wants more outputs than the routine has
.routine function "main" in=0 out=0 entry=main
main:
  CALL main 1
  POP
  RET
; expect verify: BadOperand
