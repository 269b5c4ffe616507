; INTRIN pops its function's arguments: DIVU takes two, the stack holds one
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 1
  INTRIN DIVU
  POP
  RET
; expect verify: StackUnderflow
