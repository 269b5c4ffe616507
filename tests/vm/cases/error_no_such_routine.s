; Run-time error NoSuchRoutine: the image has one routine (number 0); starting number 1 is refused.
.global int "ran" 1
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 1
  STG ran
  RET
; entry number: 1
; expect start: error NoSuchRoutine
; expect ran = 0
