; the global of a packed global and immediate (REMGKEOL's B: 1 | 3 << 16) past the table
.routine function "main" in=0 out=0 entry=main
.global int "g" 1
main:
  REMGKEOL g 196609
  RET
; expect verify: BadGlobal
