; Gold's check of a float result before it is stored (`x = a * b`, codegen's overflow test:
; |x| < 1e37, else error Overflow, RAISE 16): base code that the machine fuses at load into
; JLTFABSK (vm/fused.def). 1.5 * 2.0 = 3.0 passes and is stored; 1e30 * 1e30 (infinite) does not.
.global float "x" 1
.global float "y" 1
.const float 1.5
.const float 2.0
.const float 9.99999993e+36
.const float 1.0e30
.routine function "main" in=0 out=0 entry=main
main:
  PUSHK 0
  PUSHK 1
  MULF
  DUP
  ABSF
  PUSHK 2
  CMPF 2
  JNZ ok
  RAISE 16
ok:
  STG x
  PUSHK 3
  PUSHK 3
  MULF
  DUP
  ABSF
  PUSHK 2
  CMPF 2
  JNZ ok2
  RAISE 16
ok2:
  STG y
  RET
; expect end: error Overflow
; expect x = 3.0
; expect y = 0.0
