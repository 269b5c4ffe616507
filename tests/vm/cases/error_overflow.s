; Run-time error Overflow: a MULDIV quotient that is no int (ST: "a result outside int32 is a
; run-time error"). 65536 * 65536 / 1 = 2^32.
.global int "before" 1
.global int "r" 1
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 1
  STG before
  PUSHI 65536
  PUSHI 65536
  PUSHI 1
  MULDIV
  STG r
  RET
; expect end: error Overflow
; expect before = 1
; expect r = 0
