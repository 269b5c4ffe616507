; a float comparison with no such relation (0..5 are == != < <= > >=)
.const float 1.5
.routine function "main" in=0 out=0 entry=main
main:
  PUSHK 0
  PUSHK 0
  CMPF 7
  POP
  RET
; expect verify: BadOperand
