; Float arithmetic in float32, and the math functions of Gold manual 1.7.
.global float "f" 8
.global int "s" 2
.const float 3.2
.const float 4
.const float 2
.const float 16
.const float -625
.const float 0
.const float -4.5
.const float 1.5
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 0
  PUSHK 0
  PUSHK 1
  ADDF
  PUSHK 2
  DIVF
  STGX f            ; (3.2+4)/2 = 3.6 in float32
  PUSHI 1
  PUSHK 1
  PUSHK 7
  MULF
  PUSHK 2
  SUBF
  STGX f            ; 4*1.5-2 = 4
  PUSHI 2
  PUSHK 3
  SQRTF
  STGX f            ; sqrt(16) = 4
  PUSHI 3
  PUSHK 4
  SQRTF
  STGX f            ; sqrt(-625) = 0 (manual 1.7)
  PUSHI 4
  PUSHK 5
  SINF
  PUSHK 5
  COSF
  ADDF
  STGX f            ; sin(0)+cos(0) = 1
  PUSHI 5
  PUSHK 6
  NEGF
  STGX f            ; -(-4.5)
  PUSHI 6
  PUSHK 6
  ABSF
  STGX f            ; abs(-4.5)
  PUSHI 0
  PUSHK 6
  SIGNF
  STGX s            ; sign(-4.5)
  PUSHI 1
  PUSHK 7
  SIGNF
  STGX s            ; sign(1.5)
  RET
; expect end: finished
; expect f[0] = 3.6
; expect f[1] = 4.0
; expect f[2] = 4.0
; expect f[3] = 0.0
; expect f[4] = 1.0
; expect f[5] = 4.5
; expect f[6] = 4.5
; expect s[0] = -1
; expect s[1] = 1
