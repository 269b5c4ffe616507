; a global's comparison with a constant (JGTGK's B: global 0 | constant 1 << 16) whose
; constant is past the table
.routine function "main" in=0 out=0 entry=main
.global int "g" 1
.const int 5
main:
  JGTGK done 65536
done:
  RET
; expect verify: BadConstant
