; A procedure's statement of one operator on its frame words (PDL's `t=b*c;`, `d=b-a;`,
; `t+=a;`: two words of the frame in the data memory, + - * of ints or of floats, the result
; stored in a third): base code that the machine fuses at load into OPIMLS (ints) and OPFMLS
; (floats, run by OPIMLS's handler); a division, which may raise its error, stays base code.
; The data memory is the globals' words: `mem` is words 0..19, fp = 2, so fp + k is mem[2 + k].
; Int operators wrap (support/arith.h); 1.5 and 0.25 and their results are exact in float32.
.const int 2147483647   ; k0
.const float 1.5        ; k1
.const float 0.25       ; k2
.global int "mem" 20
.routine function "main" in=0 out=0 entry=main
.local int "fp"
main:
  PUSHI 2
  STL 0
  PUSHI 40
  LDL 0
  PUSHI 1
  ADDI
  SWAP
  STM              ; mem[3] = 40
  PUSHI 2
  LDL 0
  PUSHI 2
  ADDI
  SWAP
  STM              ; mem[4] = 2
  PUSHK 0
  LDL 0
  PUSHI 6
  ADDI
  SWAP
  STM              ; mem[8] = 2^31 - 1
  PUSHK 1
  LDL 0
  PUSHI 9
  ADDI
  SWAP
  STM              ; mem[11] = 1.5
  PUSHK 2
  LDL 0
  PUSHI 10
  ADDI
  SWAP
  STM              ; mem[12] = 0.25
  LDL 0
  PUSHI 1
  ADDI
  LDM
  LDL 0
  PUSHI 2
  ADDI
  LDM
  ADDI
  LDL 0
  PUSHI 3
  ADDI
  SWAP
  STM             ; mem[5] = 40 + 2
  LDL 0
  PUSHI 2
  ADDI
  LDM
  LDL 0
  PUSHI 1
  ADDI
  LDM
  SUBI
  LDL 0
  PUSHI 4
  ADDI
  SWAP
  STM.eol         ; mem[6] = 2 - 40
  LDL 0
  PUSHI 1
  ADDI
  LDM
  LDL 0
  PUSHI 2
  ADDI
  LDM
  MULI
  LDL 0
  PUSHI 5
  ADDI
  SWAP
  STM             ; mem[7] = 40 * 2
  LDL 0
  PUSHI 6
  ADDI
  LDM
  LDL 0
  PUSHI 2
  ADDI
  LDM
  MULI
  LDL 0
  PUSHI 7
  ADDI
  SWAP
  STM             ; mem[9] = (2^31 - 1) * 2 wraps
  LDL 0
  PUSHI 6
  ADDI
  LDM
  LDL 0
  PUSHI 2
  ADDI
  LDM
  ADDI
  LDL 0
  PUSHI 8
  ADDI
  SWAP
  STM             ; mem[10] = 2^31 - 1 + 2 wraps
  LDL 0
  PUSHI 9
  ADDI
  LDM
  LDL 0
  PUSHI 10
  ADDI
  LDM
  ADDF
  LDL 0
  PUSHI 11
  ADDI
  SWAP
  STM             ; mem[13] = 1.5 + 0.25
  LDL 0
  PUSHI 9
  ADDI
  LDM
  LDL 0
  PUSHI 10
  ADDI
  LDM
  SUBF
  LDL 0
  PUSHI 12
  ADDI
  SWAP
  STM.eol         ; mem[14] = 1.5 - 0.25
  LDL 0
  PUSHI 9
  ADDI
  LDM
  LDL 0
  PUSHI 10
  ADDI
  LDM
  MULF
  LDL 0
  PUSHI 13
  ADDI
  SWAP
  STM             ; mem[15] = 1.5 * 0.25
  LDL 0
  PUSHI 9
  ADDI
  LDM
  LDL 0
  PUSHI 10
  ADDI
  LDM
  DIVF
  LDL 0
  PUSHI 14
  ADDI
  SWAP
  STM             ; mem[16] = 1.5 / 0.25 (base code)
  LDL 0
  PUSHI 6
  ADDI
  LDM
  LDL 0
  PUSHI 2
  ADDI
  LDM
  DIVI
  LDL 0
  PUSHI 15
  ADDI
  SWAP
  STM             ; mem[17] = (2^31 - 1) / 2 (base code)
  LDL 0
  PUSHI 3
  ADDI
  LDM
  LDL 0
  PUSHI 3
  ADDI
  LDM
  ADDI
  LDL 0
  PUSHI 3
  ADDI
  SWAP
  STM             ; mem[5] = 42 + 42, its own word
  RET
; expect end: finished
; expect mem[5] = 84
; expect mem[6] = -38
; expect mem[7] = 80
; expect mem[9] = -2
; expect mem[10] = -2147483647
; expect mem[13] = 1.75
; expect mem[14] = 1.25
; expect mem[15] = 0.375
; expect mem[16] = 6.0
; expect mem[17] = 1073741823
