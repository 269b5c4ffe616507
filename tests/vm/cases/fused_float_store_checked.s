; Gold's checked store of a float result into a local (`x = a * b` in a function: |x| < 1e37,
; else error Overflow, RAISE 16, before the store): base code that the machine fuses at load into
; STLFCHK (vm/fused.def), the check's jump over its RAISE not counting as entering the store.
; 1.5 * 2.0 = 3.0 passes and is stored; then a check whose jump goes past a later instruction
; (not to the store after its RAISE: no STLFCHK) and one whose store another jump also enters
; (no STLFCHK either) store 4.0 and 5.0; last, 1e30 * 1e30 (infinite) does not pass, and the
; local keeps 5.0. Each local is copied to a global to be seen.
.global float "x" 1
.global float "y" 1
.global float "z" 1
.global float "w" 1
.const float 1.5
.const float 2.0
.const float 9.99999993e+36
.const float 1.0e30
.const float 4.0
.const float 5.0
.routine function "main" in=0 out=0 entry=main
.local float "a"
.local float "b"
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
  STL 0
  LDL 0
  STG x
  PUSHK 4
  DUP
  ABSF
  PUSHK 2
  CMPF 2
  JNZ past
  RAISE 16
  STL 1
past:
  STL 1
  LDL 1
  STG y
  PUSHK 5
  PUSHI 0
  JZ entered
  DUP
  ABSF
  PUSHK 2
  CMPF 2
  JNZ entered
  RAISE 16
entered:
  STL 0
  LDL 0
  STG z
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
  STL 0
  LDL 0
  STG w
  RET
; expect end: error Overflow
; expect x = 3.0
; expect y = 4.0
; expect z = 5.0
; expect w = 0.0
