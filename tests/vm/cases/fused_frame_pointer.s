; A pointer in a frame word and its two range tests, as PDL's `*r=n;` of a pointer parameter
; starts (a pointer into the user memory, words 0..7 here, or into the task's stack, 4 words
; from a local's base): base code that the machine fuses at load into LDPMLK (vm/fused.def).
; The data memory is the globals' words: `mem` is words 0..7 (mem[0..2] unused), `ptr` word 8;
; the frame pointer fp = 8, so fp + 0 is ptr. CMPU 2 pushes 1 when a < b unsigned
; (src/bytecode/opcodes.def): control reaches in_k when ptr < 8 or ptr - base < 4, unsigned,
; and the pointer stays on top for the access, the store of 7 through it here.
; ptr = 3: inside (3 < 8), mem[3] = 7; ptr = 20, base 18: inside (2 < 4), ptr stays 20 and
; nothing is stored through it;
; ptr = 30, base 18: outside (12 >= 4); ptr = 17, base 18: outside (17 - 18 wraps).
.global int "mem" 8
.global int "ptr" 1
.global int "inside" 4
.routine function "main" in=0 out=0 entry=main
.local int "fp"
.local int "base"
main:
  PUSHI 8
  STL 0
  PUSHI 18
  STL 1
  PUSHI 3
  STG ptr
  LDL 0
  PUSHI 0
  ADDI
  LDM
  DUP
  PUSHI 8
  CMPU 2
  JNZ in_0
  DUP
  LDL 1
  SUBI
  PUSHI 4
  CMPU 2
  JNZ in_0
  POP
  JMP out_0
in_0:
  PUSHI 7
  STM              ; *ptr = 7: mem[3]
  PUSHI 0
  PUSHI 1
  STGX inside
out_0:
  PUSHI 20
  STG ptr
  LDL 0
  PUSHI 0
  ADDI
  LDM
  DUP
  PUSHI 8
  CMPU 2
  JNZ in_1
  DUP
  LDL 1
  SUBI
  PUSHI 4
  CMPU 2
  JNZ in_1
  POP
  JMP out_1
in_1:
  POP
  PUSHI 1
  PUSHI 1
  STGX inside
out_1:
  PUSHI 30
  STG ptr
  LDL 0
  PUSHI 0
  ADDI
  LDM
  DUP
  PUSHI 8
  CMPU 2
  JNZ in_2
  DUP
  LDL 1
  SUBI
  PUSHI 4
  CMPU 2
  JNZ in_2
  POP
  JMP out_2
in_2:
  POP
  PUSHI 2
  PUSHI 1
  STGX inside
out_2:
  PUSHI 17
  STG ptr
  LDL 0
  PUSHI 0
  ADDI
  LDM
  DUP
  PUSHI 8
  CMPU 2
  JNZ in_3
  DUP
  LDL 1
  SUBI
  PUSHI 4
  CMPU 2
  JNZ in_3
  POP
  JMP out_3
in_3:
  POP
  PUSHI 3
  PUSHI 1
  STGX inside
out_3:
  RET
; expect end: finished
; expect mem[3] = 7
; expect inside[0] = 1
; expect inside[1] = 1
; expect inside[2] = 0
; expect inside[3] = 0
