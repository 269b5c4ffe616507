; Run-time error TryMismatch stops the program when no try block catches it.
.global int "arr" 3
.global int "before" 1
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 1
  STG before
  ENDTRY
  RET
; expect end: error TryMismatch
; expect before = 1
