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
  STGK f 0
  STGK h 1
  STGK nan 2
  EOL
  ADDIGGEOL isum 131073    ; x + y (g1 | g2 << 16) = 22
  SUBIGGEOL idiff 65538    ; y - x (g2 | g1 << 16) = -12
  ADDFGGEOL fsum 262147    ; f + h (g3 | g4 << 16) = 5.5
  SUBFGGEOL fdiff 196612   ; h - f (g4 | g3 << 16) = 2.5
  MULFGGEOL fprod 262147   ; f * h = 6.0
  REMGKEOL rem 327681      ; x % 5 (g1 | 5 << 16) = 2
  REMGKEOL nrem 4294639623 ; idiff % -5 (g7 | 0xFFFB << 16) = -2, truncated as C does
  PUSHI 10
  STG acc
  PUSHI 7
  ADDIGEOL acc             ; acc = 10 + 7
  PUSHK 4
  STG wrapped
  PUSHI 1
  ADDIGEOL wrapped         ; 2147483647 + 1 wraps
  STGK facc 0
  PUSHK 1
  ADDFGEOL facc            ; facc = 1.5 + 4.0
  STGK fdec 1
  PUSHK 0
  SUBFGEOL fdec            ; fdec = 4.0 - 1.5: the global is the left operand
  PUSHI 0
  ADDFGK 196611            ; f + 0.25 (g3 | k3 << 16) = 1.75
  STGX pushed
  PUSHI 1
  SUBFGK 196611            ; f - 0.25 = 1.25
  STGX pushed
  PUSHI 2
  MULFGK 196612            ; h * 0.25 (g4 | k3 << 16) = 1.0
  STGX pushed
  PUSHI 3
  MULFKG 196611            ; 0.25 * f = 0.375
  STGX pushed
  JNEQFGG n0 262147        ; f == h -> False
  PUSHI 0
  PUSHI 1
  STGX taken
n0:
  JNNEFGG n1 262147        ; f != h -> True
  PUSHI 1
  PUSHI 1
  STGX taken
n1:
  JNLTFGG n2 262147        ; f < h -> True
  PUSHI 2
  PUSHI 1
  STGX taken
n2:
  JNLEFGG n3 262147        ; f <= h -> True
  PUSHI 3
  PUSHI 1
  STGX taken
n3:
  JNGTFGG n4 262147        ; f > h -> False
  PUSHI 4
  PUSHI 1
  STGX taken
n4:
  JNGEFGG n5 262147        ; f >= h -> False
  PUSHI 5
  PUSHI 1
  STGX taken
n5:
  JNEQFGGEOL n6 196613     ; nan == f (g5 | g3 << 16) -> False
  PUSHI 6
  PUSHI 1
  STGX taken
n6:
  JNNEFGGEOL n7 196613     ; nan != f -> True
  PUSHI 7
  PUSHI 1
  STGX taken
n7:
  JNLTFGGEOL n8 196613     ; nan < f -> False
  PUSHI 8
  PUSHI 1
  STGX taken
n8:
  JNLEFGGEOL n9 196613     ; nan <= f -> False
  PUSHI 9
  PUSHI 1
  STGX taken
n9:
  JNGTFGGEOL n10 196613    ; nan > f -> False
  PUSHI 10
  PUSHI 1
  STGX taken
n10:
  JNGEFGGEOL n11 262147    ; f >= h -> False
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
