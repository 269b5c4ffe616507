; a jump into the middle of an instruction
.routine function "main" in=0 out=0 entry=main
main:
  CMDGET 1 0
  JMP @1
  RET
; expect verify: BadTarget
