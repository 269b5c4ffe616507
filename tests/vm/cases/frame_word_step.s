; Base code only (format 6), as it was written of the fused instructions named below before
; they left the stored format: the machine fuses it again at load (vm/fused.def), and the
; expectations are the same, so each fused handler is checked against its base code.
; A frame's word in the data memory stepped by a constant, ending the line (`n--;` of a PDL
; parameter): INCMLKEOL adds B's immediate (its high 16 bits, signed) to the word at local A
; plus B's offset (its low 16 bits), wrapping, and checks the address: the last step's word,
; fp + 3 = 4, is past the memory's 4 words.
.const int 2147483647      ; k0
.global int "frame" 4     ; the data memory's words 0..3
.routine function "main" in=0 out=0 entry=main
.local int "fp"           ; local 0
main:
  PUSHI 1
  STL 0                   ; fp = 1
  PUSHI 1
  PUSHI 10
  STGX frame              ; frame[1] = 10, the word at fp + 0
  PUSHI 2
  PUSHK 0
  STGX frame              ; frame[2] = INT32_MAX, the word at fp + 1
  LDL 0  ; offset 0, -1: frame[1] = 9
  PUSHI 0
  ADDI
  DUP
  LDM
  PUSHI -1
  ADDI
  STM.eol
  LDL 0       ; offset 1, +1: frame[2] wraps to INT32_MIN
  PUSHI 1
  ADDI
  DUP
  LDM
  PUSHI 1
  ADDI
  STM.eol
  LDL 0      ; offset 3, +5: word 4, past the memory
  PUSHI 3
  ADDI
  DUP
  LDM
  PUSHI 5
  ADDI
  STM.eol
  RET
; expect end: error BadAddress
; expect frame[0] = 0
; expect frame[1] = 9
; expect frame[2] = -2147483648
; expect frame[3] = 0
