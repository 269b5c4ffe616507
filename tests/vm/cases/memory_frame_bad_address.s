; CALLFEOL's frame must lie in the data memory (BadAddress), which is checked before the frame's
; limit (local 1): a frame of 6 words at word 4 would end at 10, past the data memory's 8 words
; (mem, the one global), though the limit (1000) has room. Nothing is stored: its arguments
; would have gone to words 6 and 7.
.global int "mem" 8
.routine function "main" in=0 out=0 entry=main
.local int "sp"
.local int "limit"
.routine function "proc" in=3 out=0 entry=proc
.local int "sp"
.local int "limit"
.local int "fp"
main:
  PUSHI 4
  STL 0              ; sp = 4
  PUSHI 1000
  STL 1              ; limit = 1000
  PUSHI 6
  PUSHI 66
  STM                ; mem[6] = 66
  PUSHI 11
  PUSHI 22
  CALLFEOL proc 2105350   ; 6 words, 2 arguments into words 2 and 3
  RET
proc:
  RET
; expect end: error BadAddress
; expect mem[6] = 66
; expect mem[7] = 0
