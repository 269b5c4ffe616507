; CALLFEOL within the frame's limit but past the thread's 30 call frames (main's and 29 of proc)
; is CallDepth, and stores nothing. Each frame is 3 words, its one argument (7) into word 2:
; call j's frame starts at word 3(j - 1), so proc 29's argument is mem[86], and the refused
; 30th call's would have been mem[89].
.global int "mem" 100
.global int "depth" 1
.routine function "main" in=0 out=0 entry=main
.local int "sp"
.local int "limit"
.routine function "proc" in=3 out=0 entry=proc
.local int "sp"
.local int "limit"
.local int "fp"
main:
  PUSHI 100
  STL 1              ; limit = 100, sp = 0
  PUSHI 89
  PUSHI 99
  STM                ; mem[89] = 99
  PUSHI 7
  CALLFEOL proc 2101251   ; 3 words, 1 argument into word 2
  RET
proc:
  LDG depth
  PUSHI 1
  ADDI
  STG depth
  PUSHI 7
  CALLFEOL proc 2101251
  RET
; expect end: error CallDepth
; expect depth = 29
; expect mem[86] = 7
; expect mem[89] = 99
