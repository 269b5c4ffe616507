; bench/peers/loop.pup's CUP lines with one VM instruction each and no line ends: AGenData[1..3]
; as globals, each AJump[c] a compare-and-jump. 19 instructions an iteration that takes the `if`.
; Beside eol_after_each_line.s and nop_after_each_line.s (docs/dialects/pup.md, "What a line
; costs"): `uprog_bench FILE --no-peephole --then Result` prints 59999995. Without
; --no-peephole the pass fuses it (REMGK, INCG: 10.7 instructions an iteration).
.global int "I" 1        ; g0, AGenData[1]
.global int "S" 1        ; g1, AGenData[2]
.global int "Result" 1   ; g2, AGenData[3]
.const int 30000000      ; k0
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 0
  STG 1
  PUSHI 1
  STG 0
top:
  LDG 0
  PUSHK 0
  JGTI done
  LDG 0
  PUSHI 3
  REMI
  PUSHI 0
  JEQI next
  LDG 1
  LDG 0
  PUSHI 7
  REMI
  ADDI
  STG 1
next:
  LDG 0
  PUSHI 1
  ADDI
  STG 0
  JMP top
done:
  LDG 1
  STG 2
  EXIT
