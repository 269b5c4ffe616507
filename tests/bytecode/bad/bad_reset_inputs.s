; RESET starts its routine afresh with an empty stack: a routine that takes inputs cannot be
; restarted (its inputs would come from below the stack)
.routine function "main" in=0 out=0 entry=main
.routine function "start_motor" in=1 out=1 entry=start_motor
.local int "attempts"
.local int "started"
main:
  PUSHI 3
  CALL start_motor 1
  POP
  RET
start_motor:
  RESET start_motor
; expect verify: BadOperand
