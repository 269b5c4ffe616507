; two paths joining with different depths
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 1
  JZ join
  PUSHI 2
join:
  RET
; expect verify: StackMismatch
