; a pop from an empty stack
.routine function "main" in=0 out=0 entry=main
main:
  POP
  RET
; expect verify: StackUnderflow
