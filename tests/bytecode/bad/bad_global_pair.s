; the second global of a packed pair (ADDIGG's B: 0 | 1 << 16) past the table
.routine function "main" in=0 out=0 entry=main
.global int "g" 1
main:
  ADDIGG 65536
  POP
  RET
; expect verify: BadGlobal
