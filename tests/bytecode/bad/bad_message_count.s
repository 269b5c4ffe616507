; a message with more arguments than any expression stack holds
.text "x"
.routine function "main" in=0 out=0 entry=main
main:
  MSG 0 51
  RET
; expect verify: BadOperand
