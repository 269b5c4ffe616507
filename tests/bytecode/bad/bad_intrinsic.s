; INTRIN with a function number past the last of intrinsics.def (0..13)
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 1
  INTRIN 14
  POP
  RET
; expect verify: BadOperand
