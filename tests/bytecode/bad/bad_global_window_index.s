; LDGWG's window past its global (first 2, size 6 of a 5-element array)
.global int "arr" 5
.global int "i" 1
.routine function "main" in=0 out=0 entry=main
main:
  LDGWG arr 16801794
  POP
  RET
; expect verify: BadOperand
