; Run-time error BadAddress: a word address outside the data memory (here 4 words). PDL's
; pointer into task 1's stack, 0x1000 * 1 + 3, is one: the VM's memory holds only globals.
.global int "before" 1
.global int "arr" 3
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 1
  STG before
  PUSHI 3
  LDM               ; arr[2], the last word: fine
  POP
  PUSHI 0x1003
  LDM
  POP
  RET
; expect end: error BadAddress
; expect before = 1
