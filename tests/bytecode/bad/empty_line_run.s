; JLINES over a run of no lines (B 0)
.routine function "main" in=0 out=0 entry=main
main:
  JLINES fast 0
  NOP.eol
  RET
fast:
  JMP main
; expect verify: BadOperand
