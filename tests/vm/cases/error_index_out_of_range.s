; Run-time error IndexOutOfRange stops the program when no try block catches it.
.global int "arr" 3
.global int "before" 1
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 1
  STG before
  PUSHI 3
  LDGX arr
  POP
  RET
; expect end: error IndexOutOfRange
; expect before = 1
