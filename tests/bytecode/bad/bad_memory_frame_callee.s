; a memory frame's callee needs two inputs at least: the stack's pointer and the frame's
.routine function "main" in=0 out=0 entry=main
.local int "sp"
.local int "limit"
.routine function "proc" in=1 out=0 entry=proc
.local int "i0"
main:
  CALLFEOL proc 4
  RET
proc:
  RET
; expect verify: BadOperand
