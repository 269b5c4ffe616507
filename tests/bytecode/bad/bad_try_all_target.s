; a TRYALL whose catch block starts in the middle of an instruction (CMDGET's second word)
.routine function "main" in=0 out=0 entry=main
main:
  TRYALL @2
  CMDGET 1 0
  POP
  ENDTRY
  RET
; expect verify: BadTarget
