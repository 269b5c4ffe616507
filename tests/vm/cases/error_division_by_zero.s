; Run-time error DivisionByZero stops the program when no try block catches it.
.global int "arr" 3
.global int "before" 1
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 1
  STG before
  PUSHI 1
  PUSHI 0
  DIVI
  POP
  RET
; expect end: error DivisionByZero
; expect before = 1
