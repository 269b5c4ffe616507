; RESET drops every frame and starts a routine afresh; EXIT ends the program from any depth.
.global int "passes" 1
.routine function "main" in=0 out=0 entry=main
.routine function "deep" in=0 out=0 entry=deep
main:
  LDG passes
  PUSHI 1
  ADDI
  STG passes
  LDG passes
  PUSHI 3
  CMPI 2
  JZ finish
  CALL deep 0
  RET
finish:
  CALL deep 0
  RET
deep:
  LDG passes
  PUSHI 3
  CMPI 2
  JZ stop
  RESET main        ; start main again, from inside a call
stop:
  EXIT
; expect end: finished
; expect passes = 3
