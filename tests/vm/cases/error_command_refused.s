; Run-time error CommandRefused stops the program when no try block catches it.
.global int "arr" 3
.global int "before" 1
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 1
  STG before
  CMDGET 2 0
  POP
  RET
; expect end: error CommandRefused
; expect before = 1
