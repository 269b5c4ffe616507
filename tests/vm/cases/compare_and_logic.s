; Comparisons give int 0 or 1; LNOT and TRUTHF make logic values.
.global int "c" 14
.const float 2.5
.const float 0.0004
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 0
  PUSHI 3
  PUSHI 3
  CMPI 0
  STGX c
  PUSHI 1
  PUSHI 3
  PUSHI 5
  CMPI 1
  STGX c
  PUSHI 2
  PUSHI 1
  PUSHI 2
  CMPI 2
  STGX c
  PUSHI 3
  PUSHI 3
  PUSHI 2
  CMPI 3
  STGX c
  PUSHI 4
  PUSHI 3
  PUSHI 2
  CMPI 4
  STGX c
  PUSHI 5
  PUSHI 1
  PUSHI 2
  CMPI 5
  STGX c
  PUSHI 6
  PUSHK 0
  PUSHK 0
  CMPF 0
  STGX c
  PUSHI 7
  PUSHK 0
  PUSHK 1
  CMPF 1
  STGX c
  PUSHI 8
  PUSHK 1
  PUSHK 0
  CMPF 2
  STGX c
  PUSHI 9
  PUSHK 0
  PUSHK 1
  CMPF 3
  STGX c
  PUSHI 10
  PUSHK 0
  PUSHK 1
  CMPF 4
  STGX c
  PUSHI 11
  PUSHK 1
  PUSHK 0
  CMPF 5
  STGX c
  PUSHI 12
  PUSHI 4
  LNOT
  STGX c            ; !4 = 0
  PUSHI 13
  PUSHK 1
  TRUTHF
  STGX c            ; 0.0004 is not zero
  RET
; expect end: finished
; expect c[0] = 1
; expect c[1] = 1
; expect c[2] = 1
; expect c[3] = 0
; expect c[4] = 1
; expect c[5] = 0
; expect c[6] = 1
; expect c[7] = 1
; expect c[8] = 1
; expect c[9] = 0
; expect c[10] = 1
; expect c[11] = 0
; expect c[12] = 0
; expect c[13] = 1
