; a memory frame's arguments past its words: 4 words, 3 arguments from word 2
.routine function "main" in=0 out=0 entry=main
.local int "sp"
.local int "limit"
.routine function "proc" in=2 out=0 entry=proc
.local int "i0"
.local int "i1"
main:
  PUSHI 1
  PUSHI 2
  PUSHI 3
  CALLFEOL proc 2109444
  RET
proc:
  RET
; expect verify: BadOperand
