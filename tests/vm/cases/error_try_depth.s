; Run-time error TryDepth: main holds all eight try handlers when an event routine enters a
; ninth try block. The interrupted code's handlers do not catch an event routine's error, so
; the thread stops with TryDepth instead of running main's catch block.
.global int "left" 1
.global int "entered" 1
.global int "caught" 1
.routine function "main" in=0 out=0 entry=main
.routine auto "event" in=0 out=0 entry=event
main:
  TRY caught_it
  TRY caught_it
  TRY caught_it
  TRY caught_it
  TRY caught_it
  TRY caught_it
  TRY caught_it
  TRY caught_it
  PUSHI 3
  STG left
idle:
  YIELD
  LDG left
  PUSHI 1
  SUBI
  DUP
  STG left
  JNZ idle
  ENDTRY
  ENDTRY
  ENDTRY
  ENDTRY
  ENDTRY
  ENDTRY
  ENDTRY
  ENDTRY
  RET
caught_it:
  PUSHI 1
  STG caught
  RET
event:
  PUSHI 1
  STG entered
  TRY inner
  ENDTRY
  RET
inner:
  RET
; interrupt: event
; expect end: error TryDepth
; expect entered = 1
; expect caught = 0
