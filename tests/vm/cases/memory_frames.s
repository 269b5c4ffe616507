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
  STMLK 0 1               ; frame[1] = 21
  LDMLK 0 1
  PUSHI 2
  MULI
  STMLK 0 2               ; frame[2] = frame[1] * 2
  PUSHI 8
  LDMLK 0 -4              ; user[0], a negative constant: 0
  STM                      ; kept[0] = 0
  PUSHI 9
  LDMLK 0 2
  STM                      ; kept[1] = 42
  PUSHI 3                  ; below 4: taken
  JULTK t0 4
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
  JULTK t1 4
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
  JULTLK t2 196609         ; base (local 1) | 3 << 16
  POP
  JMP n2
t2:
  POP
  PUSHI 14
  PUSHI 1
  STM                      ; taken[2] = 1
n2:
  PUSHI 11                 ; 11 - 12 wraps to 2^32 - 1, not below 3: falls through
  JULTLK t3 196609
  POP
  JMP n3
t3:
  POP
  PUSHI 15
  PUSHI 1
  STM                      ; taken[3] = 1 (it must not be)
n3:
  LDMLK 1 4             ; 12 + 4 = 16: past the memory's 16 words
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
