; The data memory: every global's words in table order, global 0's word 0 at address 0, as
; PDL's user memory keeps its variables in declaration order (the word after an array is the
; next variable). LDM and STM take a word address from the stack and convert nothing; a
; pointer is an int holding an address, and its arithmetic counts words.
.global int "a" 1         ; address 0
.global int "arr" 3       ; 1..3
.global float "f" 1       ; 4
.global int "p" 1         ; 5
.global int "seen" 4      ; 6..9, the last word
.const float 1.5
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 2
  PUSHI 77
  STM               ; word 2 is arr[1]
  PUSHI 4
  PUSHK 0
  STM               ; f = 1.5, stored as its bits
  PUSHI 1
  STG p             ; p = &arr
  PUSHI 0
  LDG p
  PUSHI 3
  ADDI
  LDM               ; *p[3]: the word past arr is f
  STGX seen
  PUSHI 1
  PUSHI 1
  LDGX arr
  STGX seen         ; what STM wrote, as the element
  PUSHI 0
  PUSHI -5
  STM               ; a
  PUSHI 9
  PUSHI 42
  STM               ; the last word of the memory: seen[3]
  PUSHI 2
  PUSHI 0
  LDM
  STGX seen
  RET
; expect end: finished
; expect a = -5
; expect arr[1] = 77
; expect f = 1.5
; expect p = 1
; expect seen[0] = 1069547520
; expect seen[1] = 77
; expect seen[2] = -5
; expect seen[3] = 42
