; Base code only (format 6), as it was written of the fused instructions named below before
; they left the stored format: the machine fuses it again at load (vm/fused.def), and the
; expectations are the same, so each fused handler is checked against its base code.
; MOVG copies one global into another (`a=b;`, the peephole's LDG; STG): the source stays, and
; with the line-end mark the move ends its line.
.global int "a" 1
.global int "b" 1
.global float "f" 1
.global float "g" 1
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 42
  STG b
  LDG b
  STG.eol a
  PUSHK 0
  STG g
  LDG g
  STG f
  RET
.const float 2.5
; expect end: finished
; expect a = 42
; expect b = 42
; expect f = 2.5
; expect g = 2.5
