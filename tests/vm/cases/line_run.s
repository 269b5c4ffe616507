; Base code only (format 6), as it was written of the fused instructions named below before
; they left the stored format: the machine fuses it again at load (vm/fused.def), and the
; expectations are the same, so each fused handler is checked against its base code.
; JLINES before a run of one-instruction lines (the CUP loader's `S = S + I`, four lines): a
; slice without a line budget takes the run's fused copy (ADDIGG and the store, then JMPLN,
; which counts the four lines), which the loop's three turns count in `fused`.
.global int "s" 1
.global int "i" 1
.global int "fused" 1
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI.eol 3
  STG.eol i
top:
  JLINES copy 4
  LDG.eol s
  LDG.eol i
  ADDI.eol
  STG.eol s
next:
  LDG i
  PUSHI 1
  SUBI
  STG i
  LDG.eol i
  JNZ.eol top
  RET
copy:
  LDG fused
  PUSHI 1
  ADDI
  STG fused
  LDG 0  ; s + i (globals 0 and 1, 16 bits each)
  LDG 1
  ADDI
  STG s
  JMPLN next 4
; expect end: finished
; expect s = 6
; expect i = 0
; expect fused = 3
