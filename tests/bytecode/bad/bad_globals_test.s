; JCMPGG with a comparison of 6 (B's bits 26..28 hold 0..5 for == != < <= > >=)
.global int "a" 1
.global int "b" 1
.routine function "main" in=0 out=0 entry=main
main:
  JCMPGG main 402653184
  RET
; expect verify: BadOperand
