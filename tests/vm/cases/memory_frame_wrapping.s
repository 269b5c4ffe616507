; A CALLFEOL frame whose end wraps past 2^32 is past the data memory too (BadAddress): 6 words
; at 0xFFFFFFFD would end at 3, below the limit (0xFFFFFFFF, as the unsigned address it is).
.global int "mem" 8
.routine function "main" in=0 out=0 entry=main
.local int "sp"
.local int "limit"
.routine function "proc" in=3 out=0 entry=proc
.local int "sp"
.local int "limit"
.local int "fp"
main:
  PUSHI -3
  STL 0              ; sp = 0xFFFFFFFD
  PUSHI -1
  STL 1              ; limit = 0xFFFFFFFF
  PUSHI 11
  PUSHI 22
  CALLFEOL proc 2105350   ; 6 words, 2 arguments into words 2 and 3
  RET
proc:
  RET
; expect end: error BadAddress
; expect mem[0] = 0
; expect mem[1] = 0
; expect mem[2] = 0
