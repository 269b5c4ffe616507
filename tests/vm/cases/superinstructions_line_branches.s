; Base code only (format 6), as it was written of the fused instructions named below before
; they left the stored format: the machine fuses it again at load (vm/fused.def), and the
; expectations are the same, so each fused handler is checked against its base code.
; The branches that end their line on both paths (JxxGKEOL, JNxxFGKEOL, JNCMPFEOL with the
; comparison in B, JZGEOL, JNZGEOL), each run directly: taken[k] is 1 when test k jumps. x = 5
; (int), f = 1.5 (float).
; Where the line ends is the peephole test's (line_slices); here, where each one goes.
.global int "taken" 24
.global int "x" 1
.global float "f" 1
.global float "nan" 1
.const int 5       ; k0
.const float 1.5   ; k1
.const float bits 0x7fc00000   ; k2, a NaN
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 5
  STG x
  PUSHK 1
  STG f
  PUSHK 2
  STG nan
  LDG 1          ; x eq 5
  PUSHI 5
  JEQI.eol t0
  JMP n0
t0:
  PUSHI 0
  PUSHI 1
  STGX taken
n0:
  LDG 1          ; x ne 5
  PUSHI 5
  JNEI.eol t1
  JMP n1
t1:
  PUSHI 1
  PUSHI 1
  STGX taken
n1:
  LDG 1          ; x lt 5
  PUSHI 5
  JLTI.eol t2
  JMP n2
t2:
  PUSHI 2
  PUSHI 1
  STGX taken
n2:
  LDG 1          ; x le 5
  PUSHI 5
  JLEI.eol t3
  JMP n3
t3:
  PUSHI 3
  PUSHI 1
  STGX taken
n3:
  LDG 1          ; x gt 5
  PUSHI 5
  JGTI.eol t4
  JMP n4
t4:
  PUSHI 4
  PUSHI 1
  STGX taken
n4:
  LDG 1          ; x ge 5
  PUSHI 5
  JGEI.eol t5
  JMP n5
t5:
  PUSHI 5
  PUSHI 1
  STGX taken
n5:
  LDG 2          ; unless f eq 1.5
  PUSHK 1
  JNEQF.eol t6
  JMP n6
t6:
  PUSHI 6
  PUSHI 1
  STGX taken
n6:
  LDG 2          ; unless f ne 1.5
  PUSHK 1
  JNNEF.eol t7
  JMP n7
t7:
  PUSHI 7
  PUSHI 1
  STGX taken
n7:
  LDG 2          ; unless f lt 1.5
  PUSHK 1
  JNLTF.eol t8
  JMP n8
t8:
  PUSHI 8
  PUSHI 1
  STGX taken
n8:
  LDG 2          ; unless f le 1.5
  PUSHK 1
  JNLEF.eol t9
  JMP n9
t9:
  PUSHI 9
  PUSHI 1
  STGX taken
n9:
  LDG 2          ; unless f gt 1.5
  PUSHK 1
  JNGTF.eol t10
  JMP n10
t10:
  PUSHI 10
  PUSHI 1
  STGX taken
n10:
  LDG 2          ; unless f ge 1.5
  PUSHK 1
  JNGEF.eol t11
  JMP n11
t11:
  PUSHI 11
  PUSHI 1
  STGX taken
n11:
  LDG f
  PUSHK 1
  JNEQF.eol t12        ; unless 1.5 eq 1.5 (stack)
  JMP n12
t12:
  PUSHI 12
  PUSHI 1
  STGX taken
n12:
  LDG f
  PUSHK 1
  JNNEF.eol t13        ; unless 1.5 ne 1.5 (stack)
  JMP n13
t13:
  PUSHI 13
  PUSHI 1
  STGX taken
n13:
  LDG f
  PUSHK 1
  JNLTF.eol t14        ; unless 1.5 lt 1.5 (stack)
  JMP n14
t14:
  PUSHI 14
  PUSHI 1
  STGX taken
n14:
  LDG f
  PUSHK 1
  JNLEF.eol t15        ; unless 1.5 le 1.5 (stack)
  JMP n15
t15:
  PUSHI 15
  PUSHI 1
  STGX taken
n15:
  LDG f
  PUSHK 1
  JNGTF.eol t16        ; unless 1.5 gt 1.5 (stack)
  JMP n16
t16:
  PUSHI 16
  PUSHI 1
  STGX taken
n16:
  LDG f
  PUSHK 1
  JNGEF.eol t17        ; unless 1.5 ge 1.5 (stack)
  JMP n17
t17:
  PUSHI 17
  PUSHI 1
  STGX taken
n17:
  LDG 1          ; x is 0
  JZ.eol t18
  JMP n18
t18:
  PUSHI 18
  PUSHI 1
  STGX taken
n18:
  LDG 1          ; x is not 0
  JNZ.eol t19
  JMP n19
t19:
  PUSHI 19
  PUSHI 1
  STGX taken
n19:
  LDG nan
  PUSHK 1
  JNNEF.eol t20        ; unless NaN != 1.5: it is, no jump
  JMP n20
t20:
  PUSHI 20
  PUSHI 1
  STGX taken
n20:
  RET
; expect end: finished
; expect taken[0] = 1
; expect taken[1] = 0
; expect taken[2] = 0
; expect taken[3] = 1
; expect taken[4] = 0
; expect taken[5] = 1
; expect taken[6] = 0
; expect taken[7] = 1
; expect taken[8] = 1
; expect taken[9] = 0
; expect taken[10] = 1
; expect taken[11] = 0
; expect taken[12] = 0
; expect taken[13] = 1
; expect taken[14] = 1
; expect taken[15] = 0
; expect taken[16] = 1
; expect taken[17] = 0
; expect taken[18] = 0
; expect taken[19] = 1
; expect taken[20] = 0
