; a routine entry inside an instruction
.routine function "main" in=0 out=0 entry=main
.routine function "other" in=0 out=0 entry=@1
main:
  CMDGET 1 0
  POP
  RET
; expect verify: BadEntry
