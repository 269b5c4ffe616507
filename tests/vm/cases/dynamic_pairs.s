; Gold's promoting multiply (manual 1.5): int*int stays int when it fits (5*4 = 20) and becomes
; a float otherwise (100000*100000 = 1.0e+10). A pair is [value, tag]: tag 0 int, 1 float;
; storing a pair with two STG stores the tag first.
.global int "small_tag" 1
.global int "small" 1
.global int "big_tag" 1
.global float "big" 1
.global float "big_plus" 1
.global int "half" 1
.global float "quot" 1
.global int "mixed" 1
.global int "again_tag" 1
.global float "absf" 1
.global int "round" 1
.global int "eq" 1
.global int "lt" 1
.global int "ge" 1
.const int 100000
.const float 0.5
.const float 1e10
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 5
  PUSHI 4
  MULID
  STG small_tag
  STG small
  PUSHK 0
  PUSHK 0
  MULID
  STG big_tag
  STG big
  PUSHK 0
  PUSHK 0
  MULID
  PUSHI 3
  I2D
  ADDD
  D2F
  STG big_plus      ; 1e10 + 3, in float32 still 1e10
  PUSHI 7
  I2D
  PUSHI 2
  I2D
  DIVD
  D2IT
  STG half          ; 7/2 = 3: both int
  PUSHI 7
  I2D
  PUSHK 1
  F2D
  DIVD
  D2F
  STG quot          ; 7/0.5 = 14
  PUSHI 10
  I2D
  PUSHI 4
  I2D
  SUBD
  PUSHI 3
  I2D
  MULD
  NEGD
  ABSD
  D2IR
  STG mixed         ; |-(10-4)*3| = 18
  PUSHK 0
  I2D
  PUSHK 0
  I2D
  MULD
  STG again_tag     ; a pair product of ints promotes too
  POP
  PUSHK 1
  F2D
  NEGD
  ABSD
  D2F
  STG absf
  PUSHK 1
  F2D
  D2IR
  STG round         ; round(0.5) = 1
  PUSHI 3
  I2D
  PUSHI 3
  I2D
  CMPD 0
  STG eq
  PUSHI 2
  I2D
  PUSHK 1
  F2D
  CMPD 2
  STG lt            ; 2 < 0.5 is false
  PUSHK 0
  PUSHK 0
  MULID
  PUSHK 2
  F2D
  CMPD 5
  STG ge            ; 1e10 >= 1e10
  RET
; expect end: finished
; expect small_tag = 0
; expect small = 20
; expect big_tag = 1
; expect big = 1e10
; expect big_plus = 1e10
; expect half = 3
; expect quot = 14.0
; expect mixed = 18
; expect again_tag = 1
; expect absf = 0.5
; expect round = 1
; expect eq = 1
; expect lt = 0
; expect ge = 1
