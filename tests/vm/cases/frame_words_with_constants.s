; Base code only (format 6), as it was written of the fused instructions named below before
; they left the stored format: the machine fuses it again at load (vm/fused.def), and the
; expectations are the same, so each fused handler is checked against its base code.
; A frame's word in the data memory with a constant. ADDMLK pushes the word at local A plus
; B's first 16 bits, plus B's immediate (the high 16 bits, signed): `n - 1` of a PDL
; parameter. JCMPMKEOL jumps when the word at a local (B's bits 0..3) plus an offset (4..15)
; compares (16..18: == != < <= > >=) with the immediate (19..31, signed) and ends its line
; either way (where the line ends is the peephole test's): `if (n < 2)`. Both check the
; address: the last word read is past the memory's 8.
.global int "frame" 4     ; 0..3
.global int "got" 4       ; 4..7
.routine function "main" in=0 out=0 entry=main
.local int "fp"           ; local 0
main:
  PUSHI 1
  STL 0                   ; fp = 1
  PUSHI 27
  PUSHI 0
  SWAP
  STGX frame              ; frame[0] = 27 (an offset of -1 from fp: not reached)
  PUSHI 1
  PUSHI -5
  STGX frame              ; frame[1] = -5, the word at fp + 0
  PUSHI 2
  PUSHI 10
  STGX frame              ; frame[2] = 10, the word at fp + 1
  LDL 0     ; fp + 1, minus 1: 9
  PUSHI 1
  ADDI
  LDM
  PUSHI -1
  ADDI
  STG got
  PUSHI 1
  LDL 0         ; fp + 0, plus 2: -3
  PUSHI 0
  ADDI
  LDM
  PUSHI 2
  ADDI
  STGX got
  LDL 0    ; fp + 1 (10) < 5: no
  PUSHI 1
  ADDI
  LDM
  PUSHI 5
  JLTI.eol l1
  PUSHI 2
  PUSHI 1
  STGX got                ; got[2] = 1
l1:
  LDL 0 ; fp + 1 (10) >= 10: yes
  PUSHI 1
  ADDI
  LDM
  PUSHI 10
  JGEI.eol l2
  PUSHI 3
  PUSHI 1
  STGX got                ; got[3] = 1 (it must not be)
l2:
  LDL 0 ; fp + 0 (-5) < -1 holds: to l3
  PUSHI 0
  ADDI
  LDM
  PUSHI -1
  JLTI.eol l3
  RET
l3:
  LDL 0              ; fp + 7 = 8: past the memory
  PUSHI 7
  ADDI
  LDM
  PUSHI 0
  ADDI
  POP
  RET
; expect end: error BadAddress
; expect got[0] = 9
; expect got[1] = -3
; expect got[2] = 1
; expect got[3] = 0
