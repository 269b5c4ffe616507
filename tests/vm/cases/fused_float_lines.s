; Gold's float condition lines without an else (`if (d >= 0)`): the branch "unless", then the
; EOL that ends the line where it falls through. The machine fuses the test at load into
; JNRELFLK (a local with a constant) or JNRELFLL (with a local) and runs the EOL on its own (the
; fused forms with the EOL went: bench/fusion_census found them in one bench program only). fell[k] is 1 when test k falls through, that is when its
; relation holds (src/bytecode/opcodes.def: JNxxF jumps unless float a <rel> b; a NaN holds only
; for !=). Locals: x = 1.5, y = 4.0, q = NaN; constant k1 = 4.0.
.global int "fell" 24
.const float 1.5
.const float 4.0
.const float bits 2143289344   ; a quiet NaN
.routine function "main" in=0 out=0 entry=main
.local float "x"
.local float "y"
.local float "q"
main:
  PUSHK 0
  STL 0
  PUSHK 1
  STL 1
  PUSHK 2
  STL 2
  LDL 0   ; x == k1 (4.0) is false -> jumps
  PUSHK 1
  JNEQF t0
  EOL
  PUSHI 0
  PUSHI 1
  STGX fell
t0:
  LDL 0   ; x != k1 (4.0) is true -> falls through
  PUSHK 1
  JNNEF t1
  EOL
  PUSHI 1
  PUSHI 1
  STGX fell
t1:
  LDL 0   ; x < k1 (4.0) is true -> falls through
  PUSHK 1
  JNLTF t2
  EOL
  PUSHI 2
  PUSHI 1
  STGX fell
t2:
  LDL 0   ; x <= k1 (4.0) is true -> falls through
  PUSHK 1
  JNLEF t3
  EOL
  PUSHI 3
  PUSHI 1
  STGX fell
t3:
  LDL 0   ; x > k1 (4.0) is false -> jumps
  PUSHK 1
  JNGTF t4
  EOL
  PUSHI 4
  PUSHI 1
  STGX fell
t4:
  LDL 0   ; x >= k1 (4.0) is false -> jumps
  PUSHK 1
  JNGEF t5
  EOL
  PUSHI 5
  PUSHI 1
  STGX fell
t5:
  LDL 2   ; q == k1 (4.0) is false -> jumps
  PUSHK 1
  JNEQF t6
  EOL
  PUSHI 6
  PUSHI 1
  STGX fell
t6:
  LDL 2   ; q != k1 (4.0) is true -> falls through
  PUSHK 1
  JNNEF t7
  EOL
  PUSHI 7
  PUSHI 1
  STGX fell
t7:
  LDL 2   ; q < k1 (4.0) is false -> jumps
  PUSHK 1
  JNLTF t8
  EOL
  PUSHI 8
  PUSHI 1
  STGX fell
t8:
  LDL 2   ; q <= k1 (4.0) is false -> jumps
  PUSHK 1
  JNLEF t9
  EOL
  PUSHI 9
  PUSHI 1
  STGX fell
t9:
  LDL 2   ; q > k1 (4.0) is false -> jumps
  PUSHK 1
  JNGTF t10
  EOL
  PUSHI 10
  PUSHI 1
  STGX fell
t10:
  LDL 2   ; q >= k1 (4.0) is false -> jumps
  PUSHK 1
  JNGEF t11
  EOL
  PUSHI 11
  PUSHI 1
  STGX fell
t11:
  LDL 0   ; x == y (4.0) is false -> jumps
  LDL 1
  JNEQF t12
  EOL
  PUSHI 12
  PUSHI 1
  STGX fell
t12:
  LDL 0   ; x != y (4.0) is true -> falls through
  LDL 1
  JNNEF t13
  EOL
  PUSHI 13
  PUSHI 1
  STGX fell
t13:
  LDL 0   ; x < y (4.0) is true -> falls through
  LDL 1
  JNLTF t14
  EOL
  PUSHI 14
  PUSHI 1
  STGX fell
t14:
  LDL 0   ; x <= y (4.0) is true -> falls through
  LDL 1
  JNLEF t15
  EOL
  PUSHI 15
  PUSHI 1
  STGX fell
t15:
  LDL 0   ; x > y (4.0) is false -> jumps
  LDL 1
  JNGTF t16
  EOL
  PUSHI 16
  PUSHI 1
  STGX fell
t16:
  LDL 0   ; x >= y (4.0) is false -> jumps
  LDL 1
  JNGEF t17
  EOL
  PUSHI 17
  PUSHI 1
  STGX fell
t17:
  LDL 0   ; x == x is true -> falls through
  LDL 0
  JNEQF t18
  EOL
  PUSHI 18
  PUSHI 1
  STGX fell
t18:
  LDL 0   ; x != x is false -> jumps
  LDL 0
  JNNEF t19
  EOL
  PUSHI 19
  PUSHI 1
  STGX fell
t19:
  LDL 0   ; x < x is false -> jumps
  LDL 0
  JNLTF t20
  EOL
  PUSHI 20
  PUSHI 1
  STGX fell
t20:
  LDL 0   ; x <= x is true -> falls through
  LDL 0
  JNLEF t21
  EOL
  PUSHI 21
  PUSHI 1
  STGX fell
t21:
  LDL 0   ; x > x is false -> jumps
  LDL 0
  JNGTF t22
  EOL
  PUSHI 22
  PUSHI 1
  STGX fell
t22:
  LDL 0   ; x >= x is true -> falls through
  LDL 0
  JNGEF t23
  EOL
  PUSHI 23
  PUSHI 1
  STGX fell
t23:
  RET
; expect fell[0] = 0
; expect fell[1] = 1
; expect fell[2] = 1
; expect fell[3] = 1
; expect fell[4] = 0
; expect fell[5] = 0
; expect fell[6] = 0
; expect fell[7] = 1
; expect fell[8] = 0
; expect fell[9] = 0
; expect fell[10] = 0
; expect fell[11] = 0
; expect fell[12] = 0
; expect fell[13] = 1
; expect fell[14] = 1
; expect fell[15] = 1
; expect fell[16] = 0
; expect fell[17] = 0
; expect fell[18] = 1
; expect fell[19] = 0
; expect fell[20] = 0
; expect fell[21] = 1
; expect fell[22] = 0
; expect fell[23] = 1
; expect end: finished
