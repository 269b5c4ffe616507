; Base code only (format 6), as it was written of the fused instructions named below before
; they left the stored format: the machine fuses it again at load (vm/fused.def), and the
; expectations are the same, so each fused handler is checked against its base code.
; INCGJMPLN, a loop's step in fused code: the CUP loader's `I = I + k` and the JMPLN after it
; in one instruction. B packs the global (bits 0..15), the step (-128..127, bits 16..23) and the
; line ends it counts (bits 24..31). Without a line budget JLINES takes the fused code, whose
; steps count i down by 3 from 30 and `up` up by 1; `rounds` counts the turns.
.global int "i" 1
.global int "up" 1
.global int "rounds" 1
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI.eol 30
  STG.eol i
top:
  JLINES fused 3
  LDG.eol i
  JZ.eol done
  LDG i
  PUSHI 3
  SUBI
  STG.eol i
  JMP.eol top
fused:
  LDG 0               ; i == 0
  JZ done
  LDG rounds
  PUSHI 1
  ADDI
  STG rounds
  LDG 0  ; global 0 (i), step -3 (0xFD), 2 line ends
  PUSHI -3
  ADDI
  STG.eol 0
  JMPLN step 1
step:
  LDG 1   ; global 1 (up), step 1, 1 line end
  PUSHI 1
  ADDI
  STG.eol 1
  JMPLN top 0
done:
  RET
; expect end: finished
; expect i = 0
; expect up = 10
; expect rounds = 10
