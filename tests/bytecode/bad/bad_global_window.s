; a window (LDGW's B: first 2, size 3) past the end of its global: g has 4 elements, 0..3
.routine function "main" in=0 out=0 entry=main
.global int "g" 4
main:
  PUSHI 1
  LDGW g 196610
  POP
  RET
; expect verify: BadOperand
