; Base code only (format 6), as it was written of the fused instructions named below before
; they left the stored format: the machine fuses it again at load (vm/fused.def), and the
; expectations are the same, so each fused handler is checked against its base code.
; A frame in the data memory, as PDL's procedures keep theirs: its words at a local's address
; plus a constant (LDMLK, STMLK), and the unsigned range tests of an address that keep it on the
; stack (JULTK, JULTLK), as PDL translates a pointer. The memory is the globals' words.
.global int "user" 4       ; 0..3
.global int "frame" 4      ; 4..7: the frame, fp = 4
.global int "kept" 4       ; 8..11
.global int "taken" 4      ; 12..15
.routine function "main" in=0 out=0 entry=main
.local int "fp"           ; local 0
.local int "base"         ; local 1
main:
  PUSHI 4
  STL 0
  PUSHI 12
  STL 1
  PUSHI 21
  LDL 0               ; frame[1] = 21
  PUSHI 1
  ADDI
  SWAP
  STM
  LDL 0
  PUSHI 1
  ADDI
  LDM
  PUSHI 2
  MULI
  LDL 0               ; frame[2] = frame[1] * 2
  PUSHI 2
  ADDI
  SWAP
  STM
  PUSHI 8
  LDL 0              ; user[0], a negative constant: 0
  PUSHI -4
  ADDI
  LDM
  STM                      ; kept[0] = 0
  PUSHI 9
  LDL 0
  PUSHI 2
  ADDI
  LDM
  STM                      ; kept[1] = 42
  PUSHI 3                  ; below 4: taken
  DUP
  PUSHI 4
  CMPU 2
  JNZ t0
  POP
  JMP n0
t0:
  PUSHI 2
  SWAP
  STGX kept                ; kept[2] = 3, the operand kept
  PUSHI 12
  PUSHI 1
  STM                      ; taken[0] = 1
n0:
  PUSHI 4                  ; not below 4: falls through, the operand kept
  DUP
  PUSHI 4
  CMPU 2
  JNZ t1
  PUSHI 3
  SWAP
  STGX kept                ; kept[3] = 4
  JMP n1
t1:
  POP
  PUSHI 13
  PUSHI 1
  STM                      ; taken[1] = 1 (it must not be)
n1:
  PUSHI 14                 ; 14 - base (12) = 2, below 3: taken
  DUP         ; base (local 1) | 3 << 16
  LDL 1
  SUBI
  PUSHI 3
  CMPU 2
  JNZ t2
  POP
  JMP n2
t2:
  POP
  PUSHI 14
  PUSHI 1
  STM                      ; taken[2] = 1
n2:
  PUSHI 11                 ; 11 - 12 wraps to 2^32 - 1, not below 3: falls through
  DUP
  LDL 1
  SUBI
  PUSHI 3
  CMPU 2
  JNZ t3
  POP
  JMP n3
t3:
  POP
  PUSHI 15
  PUSHI 1
  STM                      ; taken[3] = 1 (it must not be)
n3:
  LDL 1             ; 12 + 4 = 16: past the memory's 16 words
  PUSHI 4
  ADDI
  LDM
  POP
  RET
; expect end: error BadAddress
; expect frame[1] = 21
; expect frame[2] = 42
; expect kept[0] = 0
; expect kept[1] = 42
; expect kept[2] = 3
; expect kept[3] = 4
; expect taken[0] = 1
; expect taken[1] = 0
; expect taken[2] = 1
; expect taken[3] = 0
