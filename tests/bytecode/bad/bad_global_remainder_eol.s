; a line-ending remainder stored (REMGKEOL) whose packed immediate is 0 (g | 0 << 16)
.routine function "main" in=0 out=0 entry=main
.global int "g" 1
main:
  REMGKEOL g 0
  RET
; expect verify: BadOperand
