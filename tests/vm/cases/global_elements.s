; LDGE and STGE reach an element of a global array at a fixed index (AGenData[n] in CUP): the
; store goes to element 2 only, and the loads read elements 0 and 2 back.
.global int "data" 4
.global int "first" 1
.global int "third" 1
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 11
  STGE data 0
  PUSHI 33
  STGE.eol data 2
  LDGE data 0
  STG first
  LDGE data 2
  PUSHI 1
  ADDI
  STG third
  RET
; expect end: finished
; expect data[0] = 11
; expect data[1] = 0
; expect data[2] = 33
; expect data[3] = 0
; expect first = 11
; expect third = 34
