; Run-time error Domain: an intrinsic function's argument outside its domain (the square root
; of a negative number) stops the program, as PUP's AMath[8] does with error 31.
.global int "before" 1
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 1
  STG before
  PUSHI -1
  INTRIN ISQRT
  POP
  RET
; expect end: error Domain
; expect before = 1
