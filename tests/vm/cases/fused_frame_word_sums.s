; Two words of a frame in the data memory added (PDL's `a + b` of two parameters, `t+=a;`),
; fused at load into ADDMLML, and subtracted (base code: no program subtracts two frame words):
; the data memory is the globals' words, `mem` is words 0..7, fp = 2, so fp + 1 is mem[3] and
; fp + 2 is mem[4]. The sum wraps.
.const int 2147483647
.global int "mem" 8
.global int "sum" 1
.global int "difference" 1
.global int "wrapped" 1
.routine function "main" in=0 out=0 entry=main
.local int "fp"
main:
  PUSHI 2
  STL 0
  LDL 0
  PUSHI 1
  ADDI
  PUSHI 40
  STM              ; mem[3] = 40
  LDL 0
  PUSHI 2
  ADDI
  PUSHI 2
  STM              ; mem[4] = 2
  LDL 0
  PUSHI 1
  ADDI
  LDM
  LDL 0
  PUSHI 2
  ADDI
  LDM
  ADDI
  STG sum          ; 40 + 2 (ADDMLML)
  LDL 0
  PUSHI 2
  ADDI
  LDM
  LDL 0
  PUSHI 1
  ADDI
  LDM
  SUBI
  STG difference   ; 2 - 40
  LDL 0
  PUSHI 1
  ADDI
  PUSHK 0
  STM              ; mem[3] = 2^31 - 1
  LDL 0
  PUSHI 1
  ADDI
  LDM
  LDL 0
  PUSHI 2
  ADDI
  LDM
  ADDI
  STG wrapped      ; 2^31 - 1 + 2 wraps to -2^31 + 1
  RET
; expect end: finished
; expect sum = 42
; expect difference = -38
; expect wrapped = -2147483647
