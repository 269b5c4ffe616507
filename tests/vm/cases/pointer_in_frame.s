; Base code only (format 6), as it was written of the fused instructions named below before
; they left the stored format: the machine fuses it again at load (vm/fused.def), and the
; expectations are the same, so each fused handler is checked against its base code.
; LDPMLK: a pointer read from a frame's word in the data memory (PDL's *r of a pointer
; parameter), then PDL's two common checks of it at once: the jump is taken when the pointer is
; below the bound (the user memory) or within a window of 2^n words from a local (the task's
; own stack), and the pointer stays on the stack either way. B packs the frame's local (bits
; 0..3), the word's offset (4..11), the bound (12..23), the window's local (24..27) and n
; (28..31): 553664544 is the word at local 0 + 2, the bound 4, the window from local 1 of
; 2^2 words (2 << 4 | 4 << 12 | 1 << 24 | 2 << 28).
.global int "user" 4       ; 0..3
.global int "frame" 4      ; 4..7: fp = 4
.global int "stack" 4      ; 8..11: the window, base = 8
.global int "taken" 4
.global int "seen" 4
.routine function "main" in=0 out=0 entry=main
.local int "fp"            ; local 0
.local int "base"          ; local 1
main:
  PUSHI 4
  STL 0
  PUSHI 8
  STL 1
  PUSHI 6
  PUSHI 3
  STM                      ; frame[2] = 3: below the bound
  LDL 0
  PUSHI 2
  ADDI
  LDM
  DUP
  PUSHI 4
  CMPU 2
  JNZ t0
  DUP
  LDL 1
  SUBI
  PUSHI 4
  CMPU 2
  JNZ t0
  STG seen
  JMP n0
t0:
  PUSHI 0
  SWAP
  STGX seen                ; seen[0] = 3
  PUSHI 0
  PUSHI 1
  STGX taken
n0:
  PUSHI 6
  PUSHI 11
  STM                      ; frame[2] = 11: the window's last word
  LDL 0
  PUSHI 2
  ADDI
  LDM
  DUP
  PUSHI 4
  CMPU 2
  JNZ t1
  DUP
  LDL 1
  SUBI
  PUSHI 4
  CMPU 2
  JNZ t1
  POP
  JMP n1
t1:
  PUSHI 1
  SWAP
  STGX seen                ; seen[1] = 11
  PUSHI 1
  PUSHI 1
  STGX taken
n1:
  PUSHI 6
  PUSHI 12
  STM                      ; frame[2] = 12: past the window
  LDL 0
  PUSHI 2
  ADDI
  LDM
  DUP
  PUSHI 4
  CMPU 2
  JNZ t2
  DUP
  LDL 1
  SUBI
  PUSHI 4
  CMPU 2
  JNZ t2
  PUSHI 2
  SWAP
  STGX seen                ; seen[2] = 12, falling through
  JMP n2
t2:
  POP
  PUSHI 2
  PUSHI 1
  STGX taken               ; (it must not be)
n2:
  PUSHI 6
  PUSHI 5
  STM                      ; frame[2] = 5: between the bound and the window
  LDL 0
  PUSHI 2
  ADDI
  LDM
  DUP
  PUSHI 4
  CMPU 2
  JNZ t3
  DUP
  LDL 1
  SUBI
  PUSHI 4
  CMPU 2
  JNZ t3
  PUSHI 3
  SWAP
  STGX seen                ; seen[3] = 5, falling through
  PUSHI 40
  STL 0                    ; fp = 40: the frame's word past the memory
  LDL 0
  PUSHI 2
  ADDI
  LDM
  DUP
  PUSHI 4
  CMPU 2
  JNZ t3
  DUP
  LDL 1
  SUBI
  PUSHI 4
  CMPU 2
  JNZ t3
t3:
  POP
  RET
; expect end: error BadAddress
; expect seen[0] = 3
; expect seen[1] = 11
; expect seen[2] = 12
; expect seen[3] = 5
; expect taken[0] = 1
; expect taken[1] = 1
; expect taken[2] = 0
