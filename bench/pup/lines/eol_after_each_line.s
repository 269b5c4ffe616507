; one_instruction_a_line.s with an EOL after every instruction but the jump back and the exit
; (in the loop each CUP line is one instruction; a conditional jump's line ends here only when
; it falls through): a line end as an instruction of its own. `uprog_bench FILE --no-peephole
; --then Result` prints 59999995.
.global int "I" 1        ; g0, AGenData[1]
.global int "S" 1        ; g1, AGenData[2]
.global int "Result" 1   ; g2, AGenData[3]
.const int 30000000      ; k0
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 0
  EOL
  STG 1
  EOL
  PUSHI 1
  EOL
  STG 0
  EOL
top:
  LDG 0
  EOL
  PUSHK 0
  EOL
  JGTI done
  EOL
  LDG 0
  EOL
  PUSHI 3
  EOL
  REMI
  EOL
  PUSHI 0
  EOL
  JEQI next
  EOL
  LDG 1
  EOL
  LDG 0
  EOL
  PUSHI 7
  EOL
  REMI
  EOL
  ADDI
  EOL
  STG 1
  EOL
next:
  LDG 0
  EOL
  PUSHI 1
  EOL
  ADDI
  EOL
  STG 0
  EOL
  JMP top
done:
  LDG 1
  EOL
  STG 2
  EOL
  EXIT
