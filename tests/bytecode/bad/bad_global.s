; a global index past the table
.routine function "main" in=0 out=0 entry=main
.global int "g" 1
main:
  LDG 1
  POP
  RET
; expect verify: BadGlobal
