; CALLFEOL, a call whose frame is words of the data memory (PDL's procedures): the caller's
; local 0 is the memory stack's pointer, local 1 its limit. B packs the frame's words (bits
; 0..11), the arguments (12..19) and the word the first goes to (20..27): 2105350 is 6 words,
; 2 arguments into words 2 and 3. The frame's words 0 and 1 are left as they were, the words
; after the arguments set to 0; the callee's inputs are the caller's locals, but local 0 past
; the frame and the last at it, and its other locals are 0. A frame past the limit is CallDepth
; and stores nothing: the third call's arguments would have gone to mem[6] and mem[7].
.global int "mem" 16
.global int "seen" 5
.global int "after" 1
.routine function "main" in=0 out=0 entry=main
.local int "sp"      ; local 0
.local int "limit"   ; local 1
.local int "other"   ; local 2, the callee's third input
.routine function "proc" in=4 out=0 entry=proc
.local int "sp"
.local int "limit"
.local int "other"
.local int "fp"
.local int "scratch" ; not an input
main:
  PUSHI 2
  STL 0              ; sp = 2: the frame is mem[2..7]
  PUSHI 8
  STL 1              ; limit = 8: the frame ends there
  PUSHI 7
  STL 2
  PUSHI 2
  PUSHI 55
  STM                ; mem[2] = 55: the frame's word 0, kept
  PUSHI 6
  PUSHI 99
  STM                ; mem[6] = 99: set to 0 by the call
  PUSHI 7
  PUSHI 99
  STM
  PUSHI 8
  PUSHI 44
  STM                ; mem[8] = 44: past the frame, kept
  PUSHI 1000         ; below the arguments: still there after the call
  PUSHI 11
  PUSHI 22
  CALLFEOL proc 2105350
  PUSHI 11
  PUSHI 22
  CALLFEOL proc 2105350   ; again: the scratch local the first call set is 0 again
  STG after
  PUSHI 7
  PUSHI 77
  STM                ; mem[7] = 77
  PUSHI 4
  STL 0              ; sp = 4: the frame would end at 10, past the limit
  PUSHI 33
  PUSHI 34
  CALLFEOL proc 2105350
  PUSHI 1
  STG after
  RET
proc:
  PUSHI 0
  LDL 0
  STGX seen
  PUSHI 1
  LDL 1
  STGX seen
  PUSHI 2
  LDL 2
  STGX seen
  PUSHI 3
  LDL 3
  STGX seen
  PUSHI 4
  LDL 4
  STGX seen
  PUSHI 5
  STL 4
  RET
; expect end: error CallDepth
; expect mem[2] = 55
; expect mem[3] = 0
; expect mem[4] = 11
; expect mem[5] = 22
; expect mem[6] = 0
; expect mem[7] = 77
; expect mem[8] = 44
; expect seen[0] = 8
; expect seen[1] = 8
; expect seen[2] = 7
; expect seen[3] = 2
; expect seen[4] = 0
; expect after = 1000
