; a remainder of a global by an immediate 0 (REMGK's B), which the fused form never checks
.routine function "main" in=0 out=0 entry=main
.global int "g" 1
main:
  REMGK g 0
  POP
  RET
; expect verify: BadOperand
