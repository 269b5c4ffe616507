; Narrow and unsigned integers. SEXT keeps the low A bits sign-extended: ST's BYTE and WORD
; (-128..127, -32768..32767 in the S300 manual) and PDL's short. ZEXT keeps them zero-extended:
; PDL's loop count, an unsigned 16-bit number. SHRU and CMPU read words as unsigned.
.global int "narrow" 8
.global int "shru" 4
.global int "cmpu" 7
.const int 70000
.const int -1
.const int -2147483648
.const int 2147483647
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 0
  PUSHI 200
  SEXT 8
  STGX narrow       ; 200 as a BYTE
  PUSHI 1
  PUSHI 127
  SEXT 8
  STGX narrow       ; the largest BYTE stays
  PUSHI 2
  PUSHK 0
  SEXT 16
  STGX narrow       ; 70000 = 0x11170 as a WORD: 0x1170
  PUSHI 3
  PUSHI 40000
  SEXT 16
  STGX narrow       ; 0x9C40 as a WORD: 40000 - 65536
  PUSHI 4
  PUSHK 1
  ZEXT 16
  STGX narrow       ; 0xFFFF
  PUSHI 5
  PUSHI -56
  ZEXT 8
  STGX narrow       ; 0xC8
  PUSHI 6
  PUSHI 3
  SEXT 1
  STGX narrow       ; bit 0 is the sign
  PUSHI 7
  PUSHK 1
  ZEXT 31
  STGX narrow       ; 0x7FFFFFFF
  PUSHI 0
  PUSHI -8
  PUSHI 1
  SHRU
  STGX shru         ; 0xFFFFFFF8 >> 1, zero-filled
  PUSHI 1
  PUSHK 1
  PUSHI 28
  SHRU
  STGX shru
  PUSHI 2
  PUSHK 1
  PUSHI 32
  SHRU
  STGX shru         ; every bit shifted out
  PUSHI 3
  PUSHI 5
  PUSHI -1
  SHRU
  STGX shru
  PUSHI 0
  PUSHK 1
  PUSHI 1
  CMPU 2
  STGX cmpu         ; 0xFFFFFFFF < 1
  PUSHI 1
  PUSHI 1
  PUSHK 1
  CMPU 2
  STGX cmpu         ; 1 < 0xFFFFFFFF
  PUSHI 2
  PUSHK 1
  PUSHK 1
  CMPU 5
  STGX cmpu         ; >=
  PUSHI 3
  PUSHK 2
  PUSHK 3
  CMPU 4
  STGX cmpu         ; 0x80000000 > 0x7FFFFFFF
  PUSHI 4
  PUSHI 3
  PUSHI 2
  CMPU 3
  STGX cmpu         ; 3 <= 2
  PUSHI 5
  PUSHI -5
  PUSHI -5
  CMPU 0
  STGX cmpu         ; ==
  PUSHI 6
  PUSHI 4
  PUSHI 5
  CMPU 1
  STGX cmpu         ; !=
  RET
; expect end: finished
; expect narrow[0] = -56
; expect narrow[1] = 127
; expect narrow[2] = 4464
; expect narrow[3] = -25536
; expect narrow[4] = 65535
; expect narrow[5] = 200
; expect narrow[6] = -1
; expect narrow[7] = 2147483647
; expect shru[0] = 2147483644
; expect shru[1] = 15
; expect shru[2] = 0
; expect shru[3] = 0
; expect cmpu[0] = 0
; expect cmpu[1] = 1
; expect cmpu[2] = 1
; expect cmpu[3] = 1
; expect cmpu[4] = 0
; expect cmpu[5] = 1
; expect cmpu[6] = 1
