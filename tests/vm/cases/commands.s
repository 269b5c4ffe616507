; Drive commands through the Host: command 1 is ten registers, command 3 an action.
.global int "read" 2
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 42
  CMDSET 1 4        ; register 4 = 42
  PUSHI 5
  PUSHI 7
  CMDSETX 1         ; register 5 = 7
  PUSHI 0
  CMDGET 1 4
  STGX read
  PUSHI 1
  PUSHI 5
  CMDGETX 1
  STGX read
  PUSHI 2
  PUSHI 3
  CMDRUN 3 2        ; the action sums 2 + 3 into register 0
  CMDRUN 3 0
  RET
; expect end: finished
; expect read[0] = 42
; expect read[1] = 7
; expect runs = 2
