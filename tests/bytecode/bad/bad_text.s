; a message naming a text the image does not have
.text "only one"
.routine function "main" in=0 out=0 entry=main
main:
  MSG 1 0
  RET
; expect verify: BadOperand
