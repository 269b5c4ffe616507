; Integer arithmetic: + and - wrap (Gold manual 1.5: 2147483647+10 = -2147483639),
; / truncates toward zero, % keeps the dividend's sign, -INT32_MIN saturates.
.global int "wrap" 1
.global int "sub" 1
.global int "mul" 1
.global int "div" 1
.global int "divneg" 1
.global int "rem" 1
.global int "neg" 1
.global int "bits" 3
.global int "shifts" 4
.global int "absmin" 1
.global int "sign" 3
.const int 2147483647
.const int -2147483648
.routine function "main" in=0 out=0 entry=main
main:
  PUSHK 0
  PUSHI 10
  ADDI
  STG wrap          ; 2147483647 + 10
  PUSHI 3
  PUSHI 5
  SUBI
  STG sub           ; 3 - 5
  PUSHI 6
  PUSHI -7
  MULI
  STG mul           ; 6 * -7
  PUSHI 5
  PUSHI 2
  DIVI
  STG div           ; 5 / 2
  PUSHI -7
  PUSHI 2
  DIVI
  STG divneg        ; -7 / 2 truncates
  PUSHI -7
  PUSHI 3
  REMI
  STG rem           ; -7 % 3
  PUSHK 1
  NEGI
  STG neg           ; -(-2147483648) saturates
  PUSHI 0
  PUSHI 7
  PUSHI 3
  ANDI
  STGX bits         ; 7 & 3
  PUSHI 1
  PUSHI 2
  PUSHI 5
  ORI
  STGX bits         ; 0x2 | 0x5
  PUSHI 2
  PUSHI 3
  NOTI
  PUSHI 6
  XORI
  STGX bits         ; ~3 ^ 6 = -4 ^ 6
  PUSHI 0
  PUSHI 8
  PUSHI 2
  SHLI
  STGX shifts       ; 8 << 2
  PUSHI 1
  PUSHI 8
  PUSHI 2
  SHRI
  STGX shifts       ; 8 >> 2
  PUSHI 2
  PUSHI -8
  PUSHI 1
  SHRI
  STGX shifts       ; -8 >> 1 is arithmetic
  PUSHI 3
  PUSHI 1
  PUSHI 32
  SHLI
  STGX shifts       ; shifting every bit out
  PUSHK 1
  ABSI
  STG absmin        ; abs(0x80000000) saturates (manual 1.7)
  PUSHI 0
  PUSHI -9
  SIGNI
  STGX sign
  PUSHI 1
  PUSHI 0
  SIGNI
  STGX sign
  PUSHI 2
  PUSHI 42
  SIGNI
  STGX sign
  RET
; expect end: finished
; expect wrap = -2147483639
; expect sub = -2
; expect mul = -42
; expect div = 2
; expect divneg = -3
; expect rem = -1
; expect neg = 2147483647
; expect bits[0] = 3
; expect bits[1] = 7
; expect bits[2] = -6
; expect shifts[0] = 32
; expect shifts[1] = 2
; expect shifts[2] = -4
; expect shifts[3] = 0
; expect absmin = 2147483647
; expect sign[0] = -1
; expect sign[1] = 0
; expect sign[2] = 1
