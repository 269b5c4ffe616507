; Conversions: float to int rounds to nearest (manual 1.10: AC=12345.6789 reads 12346) and
; saturates (KV[10]=215.789e8 reads 2147483647); fix() truncates (fix(-3.8) = -3).
.global int "i" 6
.global float "f" 2
.const float 12345.6789
.const float 215.789e8
.const float -3.8
.const float 2.5
.const float 1.5
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 0
  PUSHK 0
  F2IR
  STGX i
  PUSHI 1
  PUSHK 1
  F2IR
  STGX i
  PUSHI 2
  PUSHK 2
  F2IT
  STGX i
  PUSHI 3
  PUSHK 2
  F2IR
  STGX i            ; rnd(-3.8) = -4
  PUSHI 4
  PUSHK 3
  F2IR
  STGX i            ; halves round away from zero
  PUSHI 5
  PUSHK 1
  NEGF
  F2IT
  STGX i            ; saturates low
  PUSHI 0
  PUSHI 5
  I2F
  PUSHI 2
  I2F
  DIVF
  STGX f            ; real(5)/2.0 = 2.5
  PUSHI 1
  PUSHI 3
  PUSHK 4
  I2F2
  ADDF
  STGX f            ; 3 + 1.5 with the int below the top converted
  RET
; expect end: finished
; expect i[0] = 12346
; expect i[1] = 2147483647
; expect i[2] = -3
; expect i[3] = -4
; expect i[4] = 3
; expect i[5] = -2147483648
; expect f[0] = 2.5
; expect f[1] = 4.5
