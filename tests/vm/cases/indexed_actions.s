; Action commands with an index computed at run time and arguments (Akribis' AProgRun[t],n):
; CMDRUNX A B pops B arguments, then the index below them. The test host's action 3 sums its
; arguments into register 0 and keeps its index.
.global int "sum" 1
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 1
  PUSHI 2
  ADDI              ; index 3
  PUSHI 10
  PUSHI 20
  CMDRUNX 3 2
  PUSHI 9
  PUSHI 4
  CMDRUNX 3 1
  CMDGET 1 0
  STG sum
  RET
; expect end: finished
; expect runs = 2
; expect action index = 9
; expect sum = 34
