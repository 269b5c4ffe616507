; a call to a routine that does not exist
.routine function "main" in=0 out=0 entry=main
main:
  CALL 3 0
  RET
; expect verify: BadRoutine
