; Timed waits yield and resume when the clock has passed; YIELD ends a slice; CLOCK reads time.
; The runner advances the clock by 100 µs per slice that is waiting.
.global int "t0" 1
.global int "t1" 1
.global int "spins" 1
.routine function "main" in=0 out=0 entry=main
main:
  CLOCK
  STG t0
  PUSHI 2
  WAIT 1000         ; wait 2 ms
  CLOCK
  STG t1
spin:
  LDG spins
  PUSHI 1
  ADDI
  STG spins
  YIELD
  LDG spins
  PUSHI 3
  CMPI 2
  JNZ spin
  RET
; expect end: finished
; expect t0 = 0
; expect t1 = 2000
; expect spins = 3
; expect clock = 2000
