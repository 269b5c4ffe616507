; JLINES counting more lines than its run ends (B: the run's 2 lines, 3 counted)
.routine function "main" in=0 out=0 entry=main
main:
  JLINES fast 196610
  NOP.eol
  NOP.eol
  RET
fast:
  JMP main
; expect verify: BadOperand
