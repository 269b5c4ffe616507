; PDL's two range tests of an address before `*p` (a pointer into the user memory, words
; 0..7 here, or into the task's stack, 4 words from a local's base): base code that the machine
; fuses at load into JULTKLK, one instruction for both tests when they jump to the same place
; (vm/fused.def). CMPU 2 pushes 1 when a < b unsigned (src/bytecode/opcodes.def), so control
; reaches in_k when p < 8 or p - base < 4, both unsigned. inside[k] is 1 when test k found p
; in one of the ranges; the address stays on the stack for the access (popped here).
.global int "inside" 6
.routine function "main" in=0 out=0 entry=main
.local int "p"
.local int "base"
main:
  PUSHI 3
  STL 0
  PUSHI 18
  STL 1
  LDL 0            ; 3 < 8 (unsigned): inside
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
  POP
  PUSHI 0
  PUSHI 1
  STGX inside
out_0:
  PUSHI 20
  STL 0
  PUSHI 18
  STL 1
  LDL 0            ; 20 >= 8, 20 - 18 = 2 < 4: inside
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
  STL 0
  PUSHI 18
  STL 1
  LDL 0            ; 30 >= 8, 30 - 18 = 12 >= 4: outside
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
  STL 0
  PUSHI 18
  STL 1
  LDL 0            ; 17 >= 8, 17 - 18 wraps to 2^32 - 1 >= 4: outside
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
  PUSHI 21
  STL 0
  PUSHI 18
  STL 1
  LDL 0            ; 21 >= 8, 21 - 18 = 3 < 4: inside
  DUP
  PUSHI 8
  CMPU 2
  JNZ in_4
  DUP
  LDL 1
  SUBI
  PUSHI 4
  CMPU 2
  JNZ in_4
  POP
  JMP out_4
in_4:
  POP
  PUSHI 4
  PUSHI 1
  STGX inside
out_4:
  PUSHI 22
  STL 0
  PUSHI 18
  STL 1
  LDL 0            ; 22 >= 8, 22 - 18 = 4 >= 4: outside
  DUP
  PUSHI 8
  CMPU 2
  JNZ in_5
  DUP
  LDL 1
  SUBI
  PUSHI 4
  CMPU 2
  JNZ in_5
  POP
  JMP out_5
in_5:
  POP
  PUSHI 5
  PUSHI 1
  STGX inside
out_5:
  RET
; expect end: finished
; expect inside[0] = 1
; expect inside[1] = 1
; expect inside[2] = 0
; expect inside[3] = 0
; expect inside[4] = 1
; expect inside[5] = 0
