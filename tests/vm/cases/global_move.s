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
  MOVG.eol a b
  PUSHK 0
  STG g
  MOVG f g
  RET
.const float 2.5
; expect end: finished
; expect a = 42
; expect b = 42
; expect f = 2.5
; expect g = 2.5
