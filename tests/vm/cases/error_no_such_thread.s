; Run-time error NoSuchThread: a machine has four threads (0..3); starting thread 4 is refused.
.global int "ran" 1
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 1
  STG ran
  RET
; thread: 4
; expect start: error NoSuchThread
; expect ran = 0
