; Run-time error BadArguments: twice takes one input; starting it with none is refused.
.global int "out" 1
.routine function "main" in=0 out=0 entry=main
.routine function "twice" in=1 out=0 entry=twice
.local int "x"
main:
  RET
twice:
  LDL 0
  LDL 0
  ADDI
  STG out
  RET
; entry: twice
; expect start: error BadArguments
; expect out = 0
