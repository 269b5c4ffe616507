; Run-time error StackOverflow: every call of grow keeps three values on the expression stack.
; A call is refused when the new frame's base plus the deepest stack any routine reaches (3)
; would pass the 50 entries: frame 17 of grow starts at entry 48, so it is refused.
.global int "depth" 1
.routine function "main" in=0 out=0 entry=main
.routine function "grow" in=0 out=0 entry=grow
main:
  CALL grow 0
  RET
grow:
  LDG depth
  PUSHI 1
  ADDI
  STG depth
  PUSHI 1
  PUSHI 2
  PUSHI 3
  CALL grow 0
  POP
  POP
  POP
  RET
; expect end: error StackOverflow
; expect depth = 16
