; a narrowing width outside 1..31 (32 keeps the whole word: no width, a mistake)
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 1
  SEXT 32
  POP
  RET
; expect verify: BadOperand
