; 64-bit integers as ST's DLONG needs them. A 64-bit value is two words [low, high]: on the
; stack the high one on top, in memory the low one first (here a global of length 2). I2W
; sign-extends an int; ADDW and SUBW wrap at 2^64 (ADDDLONG(D1,D2,V) is D1 := D2 + V).
; MULDIV (ST's MULDIV(V1,V2,V3,R)) is a * b / c with the exact 64-bit product, truncating.
.global int "big" 2
.global int "sum" 2
.global int "diff" 2
.global int "borrow" 2
.global int "around" 2
.global int "muldiv" 4
.const int -2147483648
.const int 2147483647
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 0
  PUSHI -1
  STGX big
  PUSHI 1
  PUSHI 1
  STGX big          ; big = 0x1_FFFFFFFF = 2^33 - 1
  PUSHI 0
  LDGX big
  PUSHI 1
  LDGX big
  PUSHI 1
  I2W
  ADDW              ; the carry into the high word: 2^33
  PUSHI 1
  SWAP
  STGX sum
  PUSHI 0
  SWAP
  STGX sum
  PUSHI 0
  LDGX sum
  PUSHI 1
  LDGX sum
  PUSHI 3
  I2W
  SUBW              ; the borrow from it: 2^33 - 3 = 0x1_FFFFFFFD
  PUSHI 1
  SWAP
  STGX diff
  PUSHI 0
  SWAP
  STGX diff
  PUSHK 0
  I2W
  PUSHI 1
  I2W
  SUBW              ; -2^31 - 1 = 0xFFFFFFFF_7FFFFFFF
  PUSHI 1
  SWAP
  STGX borrow
  PUSHI 0
  SWAP
  STGX borrow
  PUSHI -1
  I2W
  PUSHI 2
  I2W
  ADDW              ; (2^64 - 1) + 2 wraps to 1
  PUSHI 1
  SWAP
  STGX around
  PUSHI 0
  SWAP
  STGX around
  PUSHI 0
  PUSHI 70000
  PUSHI 70000
  PUSHI 100000
  MULDIV
  STGX muldiv       ; 4.9e9 does not fit an int; the quotient does
  PUSHI 1
  PUSHI -7
  PUSHI 3
  PUSHI 2
  MULDIV
  STGX muldiv       ; -21 / 2 truncates toward zero
  PUSHI 2
  PUSHK 1
  PUSHI 2
  PUSHI 2
  MULDIV
  STGX muldiv
  PUSHI 3
  PUSHI 100000
  PUSHI 100000
  PUSHI -300000
  MULDIV
  STGX muldiv       ; 1e10 / -3e5
  RET
; expect end: finished
; expect big[0] = -1
; expect big[1] = 1
; expect sum[0] = 0
; expect sum[1] = 2
; expect diff[0] = -3
; expect diff[1] = 1
; expect borrow[0] = 2147483647
; expect borrow[1] = -1
; expect around[0] = 1
; expect around[1] = 0
; expect muldiv[0] = 49000
; expect muldiv[1] = -10
; expect muldiv[2] = 2147483647
; expect muldiv[3] = -33333
