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
  MULIK 7919
  STG product           ; 47514
  PUSHI 65536
  MULIK 65537
  STG wrapped           ; 2^32 + 2^16 wraps to 65536
  PUSHI 47514
  REMIK 960
  STG rem               ; 47514 = 49 * 960 + 474
  PUSHI -7
  REMIK 3
  STG negrem            ; -1
  PUSHK 0
  REMIK -1
  STG minrem            ; 0
  PUSHI 100
  ADDIG g
  STG sum               ; 91
  PUSHK 1
  ADDIG g
  STG sumwrap           ; 2147483647 - 9
  PUSHI 4
  MULIK 7919
  ADDIG g
  REMIK 960
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
