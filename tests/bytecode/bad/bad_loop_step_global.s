; INCGJMPLN stepping global 1 of 1 (B's bits 0..15)
.global int "i" 1
.routine function "main" in=0 out=0 entry=main
main:
  INCGJMPLN main 16842753
; expect verify: BadGlobal
