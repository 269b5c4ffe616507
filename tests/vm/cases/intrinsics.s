; INTRIN runs a rare function (bytecode/intrinsics.def), its number in A (or its name in the
; text form). Unsigned division and remainder read both words as unsigned: -1 is 4294967295.
; The PUP functions (AG300 AMath[8], [9], [30]..[42]) take and give thousandths, angles in mrad.
.global int "r" 22
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 0
  PUSHI -1
  PUSHI 2
  INTRIN DIVU
  STGX r            ; 4294967295 / 2 = 2147483647
  PUSHI 1
  PUSHI -1
  PUSHI 10
  INTRIN REMU
  STGX r            ; 4294967295 % 10 = 5
  PUSHI 2
  PUSHI 7
  PUSHI 2
  INTRIN 0
  STGX r            ; DIVU by number: 7 / 2 = 3
  PUSHI 3
  PUSHI 17
  INTRIN ISQRT
  STGX r            ; 4 * 4 <= 17 < 5 * 5
  PUSHI 4
  PUSHI 4194303
  INTRIN ISQRT
  STGX r            ; 2047 * 2047 = 4190209 <= 4194303 < 2048 * 2048 = 4194304
  PUSHI 5
  PUSHI 3
  PUSHI 4
  INTRIN IPOW
  STGX r            ; 3^4 = 81
  PUSHI 6
  PUSHI 2
  PUSHI 31
  INTRIN IPOW
  STGX r            ; 2^31 saturates to 2147483647
  PUSHI 7
  PUSHI -2
  PUSHI 3
  INTRIN IPOW
  STGX r            ; (-2)^3 = -8
  PUSHI 8
  PUSHI 524
  INTRIN SINM
  STGX r            ; sin 0.524 = 0.50038: 500
  PUSHI 9
  PUSHI 3142
  INTRIN COSM
  STGX r            ; cos 3.142 = -0.99999996: -1000
  PUSHI 10
  PUSHI 785
  INTRIN TANM
  STGX r            ; tan 0.785 = 0.99920: 999
  PUSHI 11
  PUSHI 1000
  INTRIN ASINM
  STGX r            ; asin 1 = pi / 2 = 1.5708: 1571 mrad
  PUSHI 12
  PUSHI -1000
  INTRIN ACOSM
  STGX r            ; acos -1 = pi: 3142 mrad
  PUSHI 13
  PUSHI 1000
  INTRIN ATANM
  STGX r            ; atan 1 = pi / 4 = 0.7854: 785 mrad
  PUSHI 14
  PUSHI 1
  PUSHI -1
  INTRIN ATAN2M
  STGX r            ; atan2(1, -1) = 3 pi / 4 = 2.3562: 2356 mrad
  PUSHI 15
  PUSHI 2718
  INTRIN LNM
  STGX r            ; ln 2.718 = 0.99990: 1000
  PUSHI 16
  PUSHI 100000
  INTRIN LOG10M
  STGX r            ; log10 100 = 2: 2000
  PUSHI 17
  PUSHI 1000
  INTRIN EXPM
  STGX r            ; e = 2.71828: 2718
  PUSHI 18
  PUSHI 30000
  INTRIN EXPM
  STGX r            ; e^30 = 1.07e13 saturates to 2147483647
  PUSHI 19
  PUSHI -1
  PUSHI 1
  INTRIN DIVU
  STGX r            ; 4294967295 / 1 is -1 again as an int
  PUSHI 20
  PUSHI 0
  INTRIN COSM
  STGX r            ; cos 0 = 1: 1000
  PUSHI 21
  PUSHI 0
  PUSHI 0
  INTRIN IPOW
  STGX r            ; 0^0 = 1
  RET
; expect end: finished
; expect r[0] = 2147483647
; expect r[1] = 5
; expect r[2] = 3
; expect r[3] = 4
; expect r[4] = 2047
; expect r[5] = 81
; expect r[6] = 2147483647
; expect r[7] = -8
; expect r[8] = 500
; expect r[9] = -1000
; expect r[10] = 999
; expect r[11] = 1571
; expect r[12] = 3142
; expect r[13] = 785
; expect r[14] = 2356
; expect r[15] = 1000
; expect r[16] = 2000
; expect r[17] = 2718
; expect r[18] = 2147483647
; expect r[19] = -1
; expect r[20] = 1000
; expect r[21] = 1
