; a local index past the routine's locals
.routine function "main" in=0 out=0 entry=main
.local int "x"
main:
  LDL 1
  POP
  RET
; expect verify: BadLocal
