; Base code only (format 6), as it was written of the fused instructions named below before
; they left the stored format: the machine fuses it again at load (vm/fused.def), and the
; expectations are the same, so each fused handler is checked against its base code.
; The int on top with an immediate or a global, as the peephole makes them of PUSHI k; MULI,
; PUSHI k; REMI and LDG g; ADDI: C's truncating remainder (its sign the dividend's), wrapping
; products and sums, and a remainder by -1 that is 0 even for the smallest int.
.global int "g" 1
.global int "product" 1
.global int "wrapped" 1
.global int "rem" 1
.global int "negrem" 1
.global int "minrem" 1
.global int "sum" 1
.global int "sumwrap" 1
.global int "chain" 1
.const int -2147483648
.const int 2147483647
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI -9
  STG g
  PUSHI 6
  PUSHI 7919
  MULI
  STG product           ; 47514
  PUSHI 65536
  PUSHI 65537
  MULI
  STG wrapped           ; 2^32 + 2^16 wraps to 65536
  PUSHI 47514
  PUSHI 960
  REMI
  STG rem               ; 47514 = 49 * 960 + 474
  PUSHI -7
  PUSHI 3
  REMI
  STG negrem            ; -1
  PUSHK 0
  PUSHI -1
  REMI
  STG minrem            ; 0
  PUSHI 100
  LDG g
  ADDI
  STG sum               ; 91
  PUSHK 1
  LDG g
  ADDI
  STG sumwrap           ; 2147483647 - 9
  PUSHI 4
  PUSHI 7919
  MULI
  LDG g
  ADDI
  PUSHI 960
  REMI
  STG chain             ; (4 * 7919 - 9) % 960 = 31667 % 960 = 947
  RET
; expect end: finished
; expect product = 47514
; expect wrapped = 65536
; expect rem = 474
; expect negrem = -1
; expect minrem = 0
; expect sum = 91
; expect sumwrap = 2147483638
; expect chain = 947
