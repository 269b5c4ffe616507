; Base code only (format 6), as it was written of the fused instructions named below before
; they left the stored format: the machine fuses it again at load (vm/fused.def), and the
; expectations are the same, so each fused handler is checked against its base code.
; The three-address forms on globals (an assignment of two globals' arithmetic, a remainder, an
; accumulation, each ending its line), a float global with a constant, and two float globals
; compared, each run directly. x = 17, y = 5 (int); f = 1.5, h = 4.0, nan a NaN (float).
; Packed operands: the first global in bits 0..15; the second global, a constant's index or a
; signed immediate in bits 16..31. Peephole.FusesThreeAddressGlobals checks the lines they end.
.global int "taken" 12     ; g0: taken[k] is 1 when test k's condition holds
.global int "x" 1          ; g1
.global int "y" 1          ; g2
.global float "f" 1        ; g3
.global float "h" 1        ; g4
.global float "nan" 1      ; g5
.global int "isum" 1       ; g6
.global int "idiff" 1      ; g7
.global float "fsum" 1     ; g8
.global float "fdiff" 1    ; g9
.global float "fprod" 1    ; g10
.global int "rem" 1        ; g11
.global int "nrem" 1       ; g12
.global int "acc" 1        ; g13
.global float "facc" 1     ; g14
.global float "fdec" 1     ; g15
.global float "pushed" 4   ; g16
.global int "wrapped" 1    ; g17
.const float 1.5           ; k0
.const float 4.0           ; k1
.const float bits 0x7fc00000   ; k2, a NaN
.const float 0.25          ; k3
.const int 2147483647      ; k4
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 17
  STG x
  PUSHI 5
  STG y
  PUSHK 0
  STG f
  PUSHK 1
  STG h
  PUSHK 2
  STG nan
  EOL
  LDG 1    ; x + y (g1 | g2 << 16) = 22
  LDG 2
  ADDI
  STG.eol isum
  LDG 2    ; y - x (g2 | g1 << 16) = -12
  LDG 1
  SUBI
  STG.eol idiff
  LDG 3    ; f + h (g3 | g4 << 16) = 5.5
  LDG 4
  ADDF
  STG.eol fsum
  LDG 4   ; h - f (g4 | g3 << 16) = 2.5
  LDG 3
  SUBF
  STG.eol fdiff
  LDG 3   ; f * h = 6.0
  LDG 4
  MULF
  STG.eol fprod
  LDG 1      ; x % 5 (g1 | 5 << 16) = 2
  PUSHI 5
  REMI
  STG.eol rem
  LDG 7 ; idiff % -5 (g7 | 0xFFFB << 16) = -2, truncated as C does
  PUSHI -5
  REMI
  STG.eol nrem
  PUSHI 10
  STG acc
  PUSHI 7
  LDG acc             ; acc = 10 + 7
  ADDI
  STG.eol acc
  PUSHK 4
  STG wrapped
  PUSHI 1
  LDG wrapped         ; 2147483647 + 1 wraps
  ADDI
  STG.eol wrapped
  PUSHK 0
  STG facc
  PUSHK 1
  LDG facc            ; facc = 1.5 + 4.0
  ADDF
  STG.eol facc
  PUSHK 1
  STG fdec
  PUSHK 0
  LDG fdec            ; fdec = 4.0 - 1.5: the global is the left operand
  SWAP
  SUBF
  STG.eol fdec
  PUSHI 0
  LDG 3            ; f + 0.25 (g3 | k3 << 16) = 1.75
  PUSHK 3
  ADDF
  STGX pushed
  PUSHI 1
  LDG 3            ; f - 0.25 = 1.25
  PUSHK 3
  SUBF
  STGX pushed
  PUSHI 2
  LDG 4            ; h * 0.25 (g4 | k3 << 16) = 1.0
  PUSHK 3
  MULF
  STGX pushed
  PUSHI 3
  PUSHK 3            ; 0.25 * f = 0.375
  LDG 3
  MULF
  STGX pushed
  LDG 3        ; f == h -> False
  LDG 4
  JNEQF n0
  PUSHI 0
  PUSHI 1
  STGX taken
n0:
  LDG 3        ; f != h -> True
  LDG 4
  JNNEF n1
  PUSHI 1
  PUSHI 1
  STGX taken
n1:
  LDG 3        ; f < h -> True
  LDG 4
  JNLTF n2
  PUSHI 2
  PUSHI 1
  STGX taken
n2:
  LDG 3        ; f <= h -> True
  LDG 4
  JNLEF n3
  PUSHI 3
  PUSHI 1
  STGX taken
n3:
  LDG 3        ; f > h -> False
  LDG 4
  JNGTF n4
  PUSHI 4
  PUSHI 1
  STGX taken
n4:
  LDG 3        ; f >= h -> False
  LDG 4
  JNGEF n5
  PUSHI 5
  PUSHI 1
  STGX taken
n5:
  LDG 5     ; nan == f (g5 | g3 << 16) -> False
  LDG 3
  JNEQF.eol n6
  PUSHI 6
  PUSHI 1
  STGX taken
n6:
  LDG 5     ; nan != f -> True
  LDG 3
  JNNEF.eol n7
  PUSHI 7
  PUSHI 1
  STGX taken
n7:
  LDG 5     ; nan < f -> False
  LDG 3
  JNLTF.eol n8
  PUSHI 8
  PUSHI 1
  STGX taken
n8:
  LDG 5     ; nan <= f -> False
  LDG 3
  JNLEF.eol n9
  PUSHI 9
  PUSHI 1
  STGX taken
n9:
  LDG 5    ; nan > f -> False
  LDG 3
  JNGTF.eol n10
  PUSHI 10
  PUSHI 1
  STGX taken
n10:
  LDG 3    ; f >= h -> False
  LDG 4
  JNGEF.eol n11
  PUSHI 11
  PUSHI 1
  STGX taken
n11:
  RET
; expect end: finished
; expect isum = 22
; expect idiff = -12
; expect fsum = 5.5
; expect fdiff = 2.5
; expect fprod = 6.0
; expect rem = 2
; expect nrem = -2
; expect acc = 17
; expect wrapped = -2147483648
; expect facc = 5.5
; expect fdec = 2.5
; expect pushed[0] = 1.75
; expect pushed[1] = 1.25
; expect pushed[2] = 1.0
; expect pushed[3] = 0.375
; expect taken[0] = 0
; expect taken[1] = 1
; expect taken[2] = 1
; expect taken[3] = 1
; expect taken[4] = 0
; expect taken[5] = 0
; expect taken[6] = 0
; expect taken[7] = 1
; expect taken[8] = 0
; expect taken[9] = 0
; expect taken[10] = 0
; expect taken[11] = 0
