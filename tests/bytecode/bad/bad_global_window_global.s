; STGWG's index global is 2 of 2 (B's bits 24..31)
.global int "arr" 8
.global int "i" 1
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 1
  STGWG arr 33579010
  RET
; expect verify: BadGlobal
