; Accumulations' stores (`s = s + i * 2`, `f = f + i` of a local and of a global) and a
; condition's line that ends where it falls through (`if (i % 2)` without an else): base code
; the machine fuses at load into ADDISTL, ADDISTG, ADDFSTL, ADDFSTG, JZEOL and JNZEOL
; (vm/fused.def), for i = 1..4: sums 2 * 10 = 20 and 10.0, two odd and two even turns.
.global int "gsum" 1
.global float "gfsum" 1
.global int "lsum" 1
.global float "lfsum" 1
.global int "odd" 1
.global int "even" 1
.routine function "main" in=0 out=0 entry=main
.local int "i"
.local int "s"
.local float "f"
main:
  PUSHI 1
  STL 0
top:
  LDL 0
  PUSHI 4
  JGTI done
  LDL 1
  LDL 0
  PUSHI 2
  MULI
  ADDI
  STL 1          ; s = s + i * 2
  LDG gsum
  LDL 0
  PUSHI 2
  MULI
  ADDI
  STG gsum       ; gsum = gsum + i * 2
  LDL 2
  LDL 0
  I2F
  ADDF
  STL 2          ; f = f + i
  LDG gfsum
  LDL 0
  I2F
  ADDF
  STG gfsum      ; gfsum = gfsum + i
  LDL 0
  PUSHI 2
  REMI
  JZ even_turn   ; if (i % 2): odd = odd + 1
  EOL
  LDG odd
  PUSHI 1
  ADDI
  STG odd
even_turn:
  LDL 0
  PUSHI 2
  REMI
  JNZ next       ; if (!(i % 2)): even = even + 1
  EOL
  LDG even
  PUSHI 1
  ADDI
  STG even
next:
  INCL 0 1
  JMP top
done:
  LDL 1
  STG lsum
  LDL 2
  STG lfsum
  RET
; expect end: finished
; expect lsum = 20
; expect gsum = 20
; expect lfsum = 10.0
; expect gfsum = 10.0
; expect odd = 2
; expect even = 2
