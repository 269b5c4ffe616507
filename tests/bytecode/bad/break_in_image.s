; a breakpoint trap written into an image
.routine function "main" in=0 out=0 entry=main
main:
  BREAK
  RET
; expect verify: BreakInImage
