; an element of a global (LDGE's B) past the global's length: g has 3 elements, 0..2
.routine function "main" in=0 out=0 entry=main
.global int "g" 3
main:
  LDGE g 3
  POP
  RET
; expect verify: BadOperand
