; a path that runs past the last instruction
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 1
  POP
; expect verify: FallsOffEnd
