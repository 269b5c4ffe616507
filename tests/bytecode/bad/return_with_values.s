; a return that leaves values on the stack
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 1
  RET
; expect verify: ReturnWithValues
