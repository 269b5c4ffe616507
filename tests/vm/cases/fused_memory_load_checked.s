; An element of a PDL array read (`v=a[i];` with `a` at word 0 of the user memory): the
; index's range test (unsigned: a negative index is a large one), its error (RAISE 15,
; BadAddress, as PDL's compiler emits it) and the load, base code that the machine fuses at load
; into LDMCHKSTG with the store into `v`, into LDMCHK where the word is used otherwise (`u` =
; a[2] + 1) (vm/fused.def). a[2] is read; a test whose jump goes elsewhere than the load after
; its RAISE is not fused with it and runs as written (JULTK); last, the index -1 fails the test:
; the error is RAISE's, before any load, and `v` keeps the value stored before.
.global int "a" 4
.global int "i" 1
.global int "v" 1
.global int "w" 1
.global int "u" 1
.global int "under" 1
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 2
  PUSHI 42
  STM              ; a[2] = 42
  PUSHI 2
  STG i
  PUSHI 100        ; under the read: it must be on top again after it
  LDG i
  DUP
  PUSHI 4
  CMPU 2
  JNZ in
  RAISE 15
in:
  LDM
  STG v            ; v = a[2] (LDMCHKSTG)
  STG under
  LDG i
  DUP
  PUSHI 4
  CMPU 2
  JNZ in1
  RAISE 15
in1:
  LDM
  PUSHI 1
  ADDI
  STG u            ; u = a[2] + 1 (LDMCHK)
  LDG i
  DUP
  PUSHI 4
  CMPU 2
  JNZ elsewhere
  RAISE 15
  LDM
elsewhere:
  LDM
  STG w            ; w = a[2], the test not fused with a load
  PUSHI -1
  STG i
  LDG i
  DUP
  PUSHI 4
  CMPU 2
  JNZ in2
  RAISE 15
in2:
  LDM
  STG v            ; never: the index -1 is out of range
  RET
; expect end: error BadAddress
; expect v = 42
; expect w = 42
; expect u = 43
; expect under = 100
