; Loops and branches: sum i%7 for i in 1..100 not divisible by 3; DUP, SWAP, POP, NOP, INCL.
.global int "sum" 1
.global int "count" 1
.global int "swapped" 1
.routine function "main" in=0 out=0 entry=main
.local int "i"
main:
  PUSHI 1
  STL 0             ; i = 1
loop:
  LDL 0
  PUSHI 100
  CMPI 4
  JNZ done
  LDL 0
  PUSHI 3
  REMI
  JZ next           ; skip multiples of 3
  LDG sum
  LDL 0
  PUSHI 7
  REMI
  ADDI
  STG sum
  LDG count
  PUSHI 1
  ADDI
  DUP
  POP
  STG count
next:
  INCL 0 1
  NOP
  EOL
  JMP loop
done:
  PUSHI 1
  PUSHI 2
  SWAP
  SUBI
  STG swapped       ; 2 - 1
  RET
; sum: i%7 over 1..100 is 14 cycles of 1..6,0 (21 each) plus 1 → 295; the multiples of 3
; give (3k)%7 for k=1..33: 4 cycles of 3,6,2,5,1,4,0 (21 each) plus 3,6,2,5,1 → 99.
; expect end: finished
; expect sum = 196
; expect count = 67
; expect swapped = 1
