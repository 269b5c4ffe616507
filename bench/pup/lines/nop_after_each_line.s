; eol_after_each_line.s with a NOP in place of each EOL: the same dispatches, no line counted.
; `uprog_bench FILE --no-peephole --then Result` prints 59999995.
.global int "I" 1        ; g0, AGenData[1]
.global int "S" 1        ; g1, AGenData[2]
.global int "Result" 1   ; g2, AGenData[3]
.const int 30000000      ; k0
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 0
  NOP
  STG 1
  NOP
  PUSHI 1
  NOP
  STG 0
  NOP
top:
  LDG 0
  NOP
  PUSHK 0
  NOP
  JGTI done
  NOP
  LDG 0
  NOP
  PUSHI 3
  NOP
  REMI
  NOP
  PUSHI 0
  NOP
  JEQI next
  NOP
  LDG 1
  NOP
  LDG 0
  NOP
  PUSHI 7
  NOP
  REMI
  NOP
  ADDI
  NOP
  STG 1
  NOP
next:
  LDG 0
  NOP
  PUSHI 1
  NOP
  ADDI
  NOP
  STG 0
  NOP
  JMP top
done:
  LDG 1
  NOP
  STG 2
  NOP
  EXIT
