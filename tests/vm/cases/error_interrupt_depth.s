; Run-time error InterruptDepth: main and 29 frames of down fill the 30 frames, and down waits
; at the bottom. An event cannot be entered without a free frame: the entry is refused and the
; program goes on undisturbed.
.global int "event_ran" 1
.routine function "main" in=0 out=0 entry=main
.routine function "down" in=1 out=0 entry=down
.local int "n"
.routine auto "event" in=0 out=0 entry=event
main:
  PUSHI 28
  CALL down 0
  RET
down:
  LDL 0
  JZ bottom
  LDL 0
  PUSHI 1
  SUBI
  CALL down 0
  RET
bottom:
  YIELD
  RET
event:
  PUSHI 1
  STG event_ran
  RET
; interrupt: event
; expect interrupt: error InterruptDepth
; expect end: finished
; expect event_ran = 0
