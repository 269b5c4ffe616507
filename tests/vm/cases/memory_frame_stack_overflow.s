; CALLFEOL refused by the expression stack (StackOverflow), as CALL is (error_stack_overflow.s):
; every proc keeps three values on the stack, so a call is refused when the new frame's base
; plus the deepest stack any routine reaches (3) would pass the 50 entries: proc 16's call
; starts its frame at entry 48. Frames of 2 words, no arguments, within the limit.
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
  CALLFEOL proc 2097154   ; 2 words, no argument
  RET
proc:
  LDG depth
  PUSHI 1
  ADDI
  STG depth
  PUSHI 1
  PUSHI 2
  PUSHI 3
  CALLFEOL proc 2097154
  POP
  POP
  POP
  RET
; expect end: error StackOverflow
; expect depth = 16
