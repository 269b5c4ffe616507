; a wait on a command whose packed comparison (bits 8-11 of B) is 6: there are six, 0..5
.routine function "main" in=0 out=0 entry=main
main:
  UNTILCK 1 17920
  RET
; expect verify: BadOperand
