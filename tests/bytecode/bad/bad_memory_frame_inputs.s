; a memory frame's callee with more inputs than the caller has locals to give it: its inputs
; but the last (the frame's address) are the caller's first locals, 3 here
.routine function "main" in=0 out=0 entry=main
.local int "sp"
.local int "limit"
.routine function "proc" in=4 out=0 entry=proc
.local int "i0"
.local int "i1"
.local int "i2"
.local int "i3"
main:
  CALLFEOL proc 4
  RET
proc:
  RET
; expect verify: BadLocal
