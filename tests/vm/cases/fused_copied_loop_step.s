; A CUP loop's fused copy (dialects/pup/line_runs.cpp) whose path ends in the loop's step: the
; step's line is counted in the JMPLN rather than by its store's mark, so that the step and the
; way out fuse at load into INCGJLN (vm/fused.def). The run's eight one-instruction lines are
; `S = S + I` and `I = I - 1`; the copy counts its runs in `fused`: three turns from i = 3.
.global int "s" 1
.global int "i" 1
.global int "fused" 1
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI.eol 3
  STG.eol i
top:
  JLINES copy 8
  LDG.eol s
  LDG.eol i
  ADDI.eol
  STG.eol s
  LDG.eol i
  PUSHI.eol -1
  ADDI.eol
  STG.eol i
next:
  LDG.eol i
  JNZ.eol top
  RET
copy:
  LDG fused
  PUSHI 1
  ADDI
  STG fused
  LDG 0  ; s + i (globals 0 and 1)
  LDG 1
  ADDI
  STG.eol s
  LDG 1  ; i - 1, its line counted by the JMPLN with the other six
  PUSHI -1
  ADDI
  STG 1
  JMPLN next 7
; expect end: finished
; expect s = 6
; expect i = 0
; expect fused = 3
