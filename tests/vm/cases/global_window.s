; LDGW and STGW: a window of a global array indexed from 1, the index on top (CUP's
; APopParamIdx[3],AGenData[2] on elements 1..3 of `data`, B = 1 | 3 << 16 = 196609): the
; window's first and last places, and reads back through it.
.global int "data" 5
.global int "first" 1
.global int "last" 1
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 11
  PUSHI 1
  STGW data 196609
  PUSHI 33
  PUSHI 3
  STGW data 196609
  PUSHI 1
  LDGW data 196609
  STG first
  PUSHI 3
  LDGW data 196609
  STG last
  RET
; expect end: finished
; expect data[0] = 0
; expect data[1] = 11
; expect data[2] = 0
; expect data[3] = 33
; expect data[4] = 0
; expect first = 11
; expect last = 33
