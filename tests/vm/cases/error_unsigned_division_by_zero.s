; DIVU and REMU by 0 are the run-time error DivisionByZero, as DIVI's.
.global int "before" 1
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 1
  STG before
  PUSHI 5
  PUSHI 0
  INTRIN REMU
  POP
  RET
; expect end: error DivisionByZero
; expect before = 1
