; Base code only (format 6), as it was written of the fused instructions named below before
; they left the stored format: the machine fuses it again at load (vm/fused.def), and the
; expectations are the same, so each fused handler is checked against its base code.
; LDGWG and STGWG: a window of a global array indexed from 1 by another global's int (the
; peephole's LDG g; LDGW a w and LDG g; STGW a w, CUP's APushParamIdx[n],AGenData[k] with the
; index from AGenData). B packs the window's first element (bits 0..11), its size (12..23) and
; the index global (24..31): here elements 2..7 of `data`, indexed by `i`. An index past the
; window is IndexOutOfRange, although `data` has an element there, and stores nothing.
.global int "data" 10
.global int "i" 1
.global int "got" 1
.global int "after" 1
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 3
  STG i
  PUSHI 77
  LDG 1   ; data[2 + 3 - 1] = 77
  STGW data 393218
  LDG 1
  LDGW data 393218
  STG got               ; 77
  PUSHI 7
  STG i
  PUSHI 99
  LDG 1   ; i = 7: past the window's 6
  STGW data 393218
  PUSHI 1
  STG after
  RET
; expect end: error IndexOutOfRange
; expect got = 77
; expect data[4] = 77
; expect data[8] = 0
; expect after = 0
