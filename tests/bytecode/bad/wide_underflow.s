; a 64-bit add needs two pairs: four values
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 1
  PUSHI 2
  PUSHI 3
  ADDW
  POP
  POP
  RET
; expect verify: StackUnderflow
