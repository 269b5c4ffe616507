; A checked element read stored in a global (LDMCHKSTG, vm/fused.def) whose address passes the
; range test (7 < 400, the user memory's size as PDL's compiler emits it) but lies past the
; machine's data memory (the globals' 4 words): BadAddress from the load, as LDM's own check
; gives it, and `v` keeps its value.
.global int "a" 2
.global int "i" 1
.global int "v" 1
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 5
  STG v
  PUSHI 7
  STG i
  LDG i
  DUP
  PUSHI 400
  CMPU 2
  JNZ in
  RAISE 15
in:
  LDM
  STG v            ; never: word 7 is past the data memory
  RET
; expect end: error BadAddress
; expect v = 5
