; an int comparison with no such relation (0..5 are == != < <= > >=)
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 1
  PUSHI 2
  CMPI 6
  POP
  RET
; expect verify: BadOperand
