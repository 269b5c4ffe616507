; more than 50 values on the expression stack
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 1
  PUSHI 1
  PUSHI 1
  PUSHI 1
  PUSHI 1
  PUSHI 1
  PUSHI 1
  PUSHI 1
  PUSHI 1
  PUSHI 1
  PUSHI 1
  PUSHI 1
  PUSHI 1
  PUSHI 1
  PUSHI 1
  PUSHI 1
  PUSHI 1
  PUSHI 1
  PUSHI 1
  PUSHI 1
  PUSHI 1
  PUSHI 1
  PUSHI 1
  PUSHI 1
  PUSHI 1
  PUSHI 1
  PUSHI 1
  PUSHI 1
  PUSHI 1
  PUSHI 1
  PUSHI 1
  PUSHI 1
  PUSHI 1
  PUSHI 1
  PUSHI 1
  PUSHI 1
  PUSHI 1
  PUSHI 1
  PUSHI 1
  PUSHI 1
  PUSHI 1
  PUSHI 1
  PUSHI 1
  PUSHI 1
  PUSHI 1
  PUSHI 1
  PUSHI 1
  PUSHI 1
  PUSHI 1
  PUSHI 1
  PUSHI 1
  POP
  POP
  POP
  POP
  POP
  POP
  POP
  POP
  POP
  POP
  POP
  POP
  POP
  POP
  POP
  POP
  POP
  POP
  POP
  POP
  POP
  POP
  POP
  POP
  POP
  POP
  POP
  POP
  POP
  POP
  POP
  POP
  POP
  POP
  POP
  POP
  POP
  POP
  POP
  POP
  POP
  POP
  POP
  POP
  POP
  POP
  POP
  POP
  POP
  POP
  POP
  RET
; expect verify: StackOverflow
