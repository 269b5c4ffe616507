; Run-time error CallDepth: a thread holds 30 frames. main is the first, so the 29th call of
; grow fills the call stack and the 30th is refused.
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
  CALL grow 0
  RET
; expect end: error CallDepth
; expect depth = 29
