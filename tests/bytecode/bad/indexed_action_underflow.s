; an indexed action pops its arguments and then its index: one value is not enough
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 7
  CMDRUNX 3 1
  RET
; expect verify: StackUnderflow
