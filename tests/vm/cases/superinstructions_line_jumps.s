; Base code only (format 6), as it was written of the fused instructions named below before
; they left the stored format: the machine fuses it again at load (vm/fused.def), and the
; expectations are the same, so each fused handler is checked against its base code.
; The superinstructions that end a line and jump, and the constant store, run directly.
; i counts 0, 3, 6, 9 (INCLJEOL adds 3 and jumps back), then j counts down 5..1 (a step of -1);
; STLJEOL stores 42 into i and jumps over the store of 7.
.global int "sum" 1
.global int "down" 1
.global int "last" 1
.global float "half" 1
.const float 2.5
.routine function "main" in=0 out=0 entry=main
.local int "i"
.local float "f"
.local int "j"
main:
  PUSHK 0           ; f = 2.5
  STL 1
  LDL 1
  STG half
  PUSHI 0
  STL 0
up:
  LDL 0
  PUSHI 10
  CMPI 5
  JNZ counted
  LDG sum
  LDL 0
  ADDI
  STG sum
  INCL 0 3          ; i += 3 (local 0, step 3), end of line, back to up
  JMP.eol up
counted:
  PUSHI 5
  STL 2
down:
  LDL 2
  PUSHI 0
  CMPI 3
  JNZ stored
  LDG down
  LDL 2
  ADDI
  STG down
  INCL 2 -1    ; j += -1 (local 2, step -1)
  JMP.eol down
stored:
  PUSHI 42
  STL 0             ; i = 42, end of line, jump to after
  JMP.eol after
  PUSHI 7
  STL 0
after:
  LDL 0
  STG last
  RET
; expect end: finished
; expect half = 2.5
; expect sum = 18
; expect down = 15
; expect last = 42
