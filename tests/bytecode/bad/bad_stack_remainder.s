; REMIK by 0: the peephole never makes it, the verifier refuses it
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 7
  REMIK 0
  POP
  RET
; expect verify: BadOperand
