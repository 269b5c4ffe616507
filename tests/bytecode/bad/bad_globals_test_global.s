; JCMPGG naming global 2 of 2 as its second (B's bits 13..25)
.global int "a" 1
.global int "b" 1
.routine function "main" in=0 out=0 entry=main
main:
  JCMPGG main 16384
  RET
; expect verify: BadGlobal
