; The 16-bit check's shape with a RAISE of another error than Overflow (here 15, BadAddress) is
; not CHKS16 (vm/fused.def: its RAISE must be Overflow's): 40000 does not fit, and the run ends
; with the RAISE's own error, as the base code says.
.global int "reached" 1
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 40000
  DUP
  SEXT 16
  JEQI fits
  RAISE 15
fits:
  PUSHI 1
  STG reached
  RET
; expect end: error BadAddress
; expect reached = 0
