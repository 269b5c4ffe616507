; Run-time error BadAddress from the second of two frame words added (ADDMLML, fused at load):
; fp = 2 reaches mem[3]; fp + 10 is past the data memory's 8 words. The first word read fine
; does not make the sum: nothing is stored.
.global int "mem" 8
.global int "sum" 1
.routine function "main" in=0 out=0 entry=main
.local int "fp"
main:
  PUSHI 2
  STL 0
  PUSHI 7
  STG sum
  LDL 0
  PUSHI 1
  ADDI
  LDM
  LDL 0
  PUSHI 10
  ADDI
  LDM
  ADDI
  STG sum
  RET
; expect end: error BadAddress
; expect sum = 7
