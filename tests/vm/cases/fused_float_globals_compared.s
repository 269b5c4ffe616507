; Two float globals compared and the jump unless the relation holds (PDL's `if (d <= stop_d)`, every
; variable of PDL a global): base code that the machine fuses at load into JNRELFGG
; (vm/fused.def), its relation read from the jump. a = 1.0, b = 2.0, n = NaN (inf - inf); each
; flag is set to 1 where the relation holds (the jump not taken): 1 < 2, 1 <= 2 and 1 != 2 hold,
; 1 > 2, 1 >= 2 and 1 == 2 do not; with a NaN only != holds (IEEE 754: unordered); 1 >= 1 holds.
.global float "a" 1
.global float "b" 1
.global float "n" 1
.global int "lt" 1
.global int "le" 1
.global int "gt" 1
.global int "ge" 1
.global int "eq" 1
.global int "ne" 1
.global int "nan_lt" 1
.global int "nan_ne" 1
.global int "nan_eq" 1
.global int "same_ge" 1
.const float 1.0
.const float 2.0
.const float 1.0e30
.routine function "main" in=0 out=0 entry=main
main:
  PUSHK 0
  STG a
  PUSHK 1
  STG b
  PUSHK 2
  PUSHK 2
  MULF
  DUP
  SUBF
  STG n
  LDG a
  LDG b
  JNLTF skip0
  PUSHI 1
  STG lt
skip0:
  LDG a
  LDG b
  JNLEF skip1
  PUSHI 1
  STG le
skip1:
  LDG a
  LDG b
  JNGTF skip2
  PUSHI 1
  STG gt
skip2:
  LDG a
  LDG b
  JNGEF skip3
  PUSHI 1
  STG ge
skip3:
  LDG a
  LDG b
  JNEQF skip4
  PUSHI 1
  STG eq
skip4:
  LDG a
  LDG b
  JNNEF skip5
  PUSHI 1
  STG ne
skip5:
  LDG n
  LDG a
  JNLTF skip6
  PUSHI 1
  STG nan_lt
skip6:
  LDG n
  LDG a
  JNNEF skip7
  PUSHI 1
  STG nan_ne
skip7:
  LDG n
  LDG n
  JNEQF skip8
  PUSHI 1
  STG nan_eq
skip8:
  LDG a
  LDG a
  JNGEF skip9
  PUSHI 1
  STG same_ge
skip9:
  RET
; expect end: finished
; expect lt = 1
; expect le = 1
; expect gt = 0
; expect ge = 0
; expect eq = 0
; expect ne = 1
; expect nan_lt = 0
; expect nan_ne = 1
; expect nan_eq = 0
; expect same_ge = 1
