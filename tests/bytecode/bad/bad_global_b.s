; a global in an instruction's second word (STGJEOL's B) past the table
.routine function "main" in=0 out=0 entry=main
.global int "g" 1
main:
  PUSHI 1
  STGJEOL done 1
done:
  RET
; expect verify: BadGlobal
