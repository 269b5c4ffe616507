; a constant index past the pool
.routine function "main" in=0 out=0 entry=main
.const int 1
main:
  PUSHK 1
  POP
  RET
; expect verify: BadConstant
