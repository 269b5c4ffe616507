; The folded compare-and-jumps of vm/fused.def (JRELGC, JRELGG, JNRELFGK): one fused
; instruction each for the six relations, which it reads from its jump's own opcode; two float
; globals compared are LDG2 and the base JNxxF since JNRELFGG went. Base code that the machine
; fuses at load; every relation of each form, the left side below, equal to and
; above the right (and a NaN). taken[k] is 1 when test k jumps; each comment gives the
; comparison and its answer by the relation's meaning (src/bytecode/opcodes.def: JxxI jumps
; when int a <rel> b, JNxxF unless float a <rel> b, so a NaN jumps for every relation but !=).
; Globals: g2 = 2, g3 = 3, g4 = 4 (int); f = 1.5, h = 4.0, n = NaN (float); constants k0 = 3
; (int), k1 = 1.5, k2 = 4.0 (float).
.global int "taken" 84
.global int "g2" 1
.global int "g3" 1
.global int "g4" 1
.global float "f" 1
.global float "h" 1
.global float "n" 1
.const int 3
.const float 1.5
.const float 4.0
.const float bits 2143289344   ; a quiet NaN
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 2
  STG g2
  PUSHI 3
  STG g3
  PUSHI 4
  STG g4
  PUSHK 1
  STG f
  PUSHK 2
  STG h
  PUSHK 3
  STG n
  LDG g2  ; g2 == k0 (3) is false -> falls through
  PUSHK 0
  JEQI t0
  JMP n0
t0:
  PUSHI 0
  PUSHI 1
  STGX taken
n0:
  LDG g2  ; g2 != k0 (3) is true -> jumps
  PUSHK 0
  JNEI t1
  JMP n1
t1:
  PUSHI 1
  PUSHI 1
  STGX taken
n1:
  LDG g2  ; g2 < k0 (3) is true -> jumps
  PUSHK 0
  JLTI t2
  JMP n2
t2:
  PUSHI 2
  PUSHI 1
  STGX taken
n2:
  LDG g2  ; g2 <= k0 (3) is true -> jumps
  PUSHK 0
  JLEI t3
  JMP n3
t3:
  PUSHI 3
  PUSHI 1
  STGX taken
n3:
  LDG g2  ; g2 > k0 (3) is false -> falls through
  PUSHK 0
  JGTI t4
  JMP n4
t4:
  PUSHI 4
  PUSHI 1
  STGX taken
n4:
  LDG g2  ; g2 >= k0 (3) is false -> falls through
  PUSHK 0
  JGEI t5
  JMP n5
t5:
  PUSHI 5
  PUSHI 1
  STGX taken
n5:
  LDG g3  ; g3 == k0 (3) is true -> jumps
  PUSHK 0
  JEQI t6
  JMP n6
t6:
  PUSHI 6
  PUSHI 1
  STGX taken
n6:
  LDG g3  ; g3 != k0 (3) is false -> falls through
  PUSHK 0
  JNEI t7
  JMP n7
t7:
  PUSHI 7
  PUSHI 1
  STGX taken
n7:
  LDG g3  ; g3 < k0 (3) is false -> falls through
  PUSHK 0
  JLTI t8
  JMP n8
t8:
  PUSHI 8
  PUSHI 1
  STGX taken
n8:
  LDG g3  ; g3 <= k0 (3) is true -> jumps
  PUSHK 0
  JLEI t9
  JMP n9
t9:
  PUSHI 9
  PUSHI 1
  STGX taken
n9:
  LDG g3  ; g3 > k0 (3) is false -> falls through
  PUSHK 0
  JGTI t10
  JMP n10
t10:
  PUSHI 10
  PUSHI 1
  STGX taken
n10:
  LDG g3  ; g3 >= k0 (3) is true -> jumps
  PUSHK 0
  JGEI t11
  JMP n11
t11:
  PUSHI 11
  PUSHI 1
  STGX taken
n11:
  LDG g4  ; g4 == k0 (3) is false -> falls through
  PUSHK 0
  JEQI t12
  JMP n12
t12:
  PUSHI 12
  PUSHI 1
  STGX taken
n12:
  LDG g4  ; g4 != k0 (3) is true -> jumps
  PUSHK 0
  JNEI t13
  JMP n13
t13:
  PUSHI 13
  PUSHI 1
  STGX taken
n13:
  LDG g4  ; g4 < k0 (3) is false -> falls through
  PUSHK 0
  JLTI t14
  JMP n14
t14:
  PUSHI 14
  PUSHI 1
  STGX taken
n14:
  LDG g4  ; g4 <= k0 (3) is false -> falls through
  PUSHK 0
  JLEI t15
  JMP n15
t15:
  PUSHI 15
  PUSHI 1
  STGX taken
n15:
  LDG g4  ; g4 > k0 (3) is true -> jumps
  PUSHK 0
  JGTI t16
  JMP n16
t16:
  PUSHI 16
  PUSHI 1
  STGX taken
n16:
  LDG g4  ; g4 >= k0 (3) is true -> jumps
  PUSHK 0
  JGEI t17
  JMP n17
t17:
  PUSHI 17
  PUSHI 1
  STGX taken
n17:
  LDG g2  ; g2 == g3 is false -> falls through
  LDG g3
  JEQI t18
  JMP n18
t18:
  PUSHI 18
  PUSHI 1
  STGX taken
n18:
  LDG g2  ; g2 != g3 is true -> jumps
  LDG g3
  JNEI t19
  JMP n19
t19:
  PUSHI 19
  PUSHI 1
  STGX taken
n19:
  LDG g2  ; g2 < g3 is true -> jumps
  LDG g3
  JLTI t20
  JMP n20
t20:
  PUSHI 20
  PUSHI 1
  STGX taken
n20:
  LDG g2  ; g2 <= g3 is true -> jumps
  LDG g3
  JLEI t21
  JMP n21
t21:
  PUSHI 21
  PUSHI 1
  STGX taken
n21:
  LDG g2  ; g2 > g3 is false -> falls through
  LDG g3
  JGTI t22
  JMP n22
t22:
  PUSHI 22
  PUSHI 1
  STGX taken
n22:
  LDG g2  ; g2 >= g3 is false -> falls through
  LDG g3
  JGEI t23
  JMP n23
t23:
  PUSHI 23
  PUSHI 1
  STGX taken
n23:
  LDG g3  ; g3 == g3 is true -> jumps
  LDG g3
  JEQI t24
  JMP n24
t24:
  PUSHI 24
  PUSHI 1
  STGX taken
n24:
  LDG g3  ; g3 != g3 is false -> falls through
  LDG g3
  JNEI t25
  JMP n25
t25:
  PUSHI 25
  PUSHI 1
  STGX taken
n25:
  LDG g3  ; g3 < g3 is false -> falls through
  LDG g3
  JLTI t26
  JMP n26
t26:
  PUSHI 26
  PUSHI 1
  STGX taken
n26:
  LDG g3  ; g3 <= g3 is true -> jumps
  LDG g3
  JLEI t27
  JMP n27
t27:
  PUSHI 27
  PUSHI 1
  STGX taken
n27:
  LDG g3  ; g3 > g3 is false -> falls through
  LDG g3
  JGTI t28
  JMP n28
t28:
  PUSHI 28
  PUSHI 1
  STGX taken
n28:
  LDG g3  ; g3 >= g3 is true -> jumps
  LDG g3
  JGEI t29
  JMP n29
t29:
  PUSHI 29
  PUSHI 1
  STGX taken
n29:
  LDG g4  ; g4 == g3 is false -> falls through
  LDG g3
  JEQI t30
  JMP n30
t30:
  PUSHI 30
  PUSHI 1
  STGX taken
n30:
  LDG g4  ; g4 != g3 is true -> jumps
  LDG g3
  JNEI t31
  JMP n31
t31:
  PUSHI 31
  PUSHI 1
  STGX taken
n31:
  LDG g4  ; g4 < g3 is false -> falls through
  LDG g3
  JLTI t32
  JMP n32
t32:
  PUSHI 32
  PUSHI 1
  STGX taken
n32:
  LDG g4  ; g4 <= g3 is false -> falls through
  LDG g3
  JLEI t33
  JMP n33
t33:
  PUSHI 33
  PUSHI 1
  STGX taken
n33:
  LDG g4  ; g4 > g3 is true -> jumps
  LDG g3
  JGTI t34
  JMP n34
t34:
  PUSHI 34
  PUSHI 1
  STGX taken
n34:
  LDG g4  ; g4 >= g3 is true -> jumps
  LDG g3
  JGEI t35
  JMP n35
t35:
  PUSHI 35
  PUSHI 1
  STGX taken
n35:
  LDG f   ; f == k1 (1.5) is true -> falls through
  PUSHK 1
  JNEQF t36
  JMP n36
t36:
  PUSHI 36
  PUSHI 1
  STGX taken
n36:
  LDG f   ; f != k1 (1.5) is false -> jumps
  PUSHK 1
  JNNEF t37
  JMP n37
t37:
  PUSHI 37
  PUSHI 1
  STGX taken
n37:
  LDG f   ; f < k1 (1.5) is false -> jumps
  PUSHK 1
  JNLTF t38
  JMP n38
t38:
  PUSHI 38
  PUSHI 1
  STGX taken
n38:
  LDG f   ; f <= k1 (1.5) is true -> falls through
  PUSHK 1
  JNLEF t39
  JMP n39
t39:
  PUSHI 39
  PUSHI 1
  STGX taken
n39:
  LDG f   ; f > k1 (1.5) is false -> jumps
  PUSHK 1
  JNGTF t40
  JMP n40
t40:
  PUSHI 40
  PUSHI 1
  STGX taken
n40:
  LDG f   ; f >= k1 (1.5) is true -> falls through
  PUSHK 1
  JNGEF t41
  JMP n41
t41:
  PUSHI 41
  PUSHI 1
  STGX taken
n41:
  LDG f   ; f == k2 (4.0) is false -> jumps
  PUSHK 2
  JNEQF t42
  JMP n42
t42:
  PUSHI 42
  PUSHI 1
  STGX taken
n42:
  LDG f   ; f != k2 (4.0) is true -> falls through
  PUSHK 2
  JNNEF t43
  JMP n43
t43:
  PUSHI 43
  PUSHI 1
  STGX taken
n43:
  LDG f   ; f < k2 (4.0) is true -> falls through
  PUSHK 2
  JNLTF t44
  JMP n44
t44:
  PUSHI 44
  PUSHI 1
  STGX taken
n44:
  LDG f   ; f <= k2 (4.0) is true -> falls through
  PUSHK 2
  JNLEF t45
  JMP n45
t45:
  PUSHI 45
  PUSHI 1
  STGX taken
n45:
  LDG f   ; f > k2 (4.0) is false -> jumps
  PUSHK 2
  JNGTF t46
  JMP n46
t46:
  PUSHI 46
  PUSHI 1
  STGX taken
n46:
  LDG f   ; f >= k2 (4.0) is false -> jumps
  PUSHK 2
  JNGEF t47
  JMP n47
t47:
  PUSHI 47
  PUSHI 1
  STGX taken
n47:
  LDG n   ; n == k1 (1.5) is false -> jumps
  PUSHK 1
  JNEQF t48
  JMP n48
t48:
  PUSHI 48
  PUSHI 1
  STGX taken
n48:
  LDG n   ; n != k1 (1.5) is true -> falls through
  PUSHK 1
  JNNEF t49
  JMP n49
t49:
  PUSHI 49
  PUSHI 1
  STGX taken
n49:
  LDG n   ; n < k1 (1.5) is false -> jumps
  PUSHK 1
  JNLTF t50
  JMP n50
t50:
  PUSHI 50
  PUSHI 1
  STGX taken
n50:
  LDG n   ; n <= k1 (1.5) is false -> jumps
  PUSHK 1
  JNLEF t51
  JMP n51
t51:
  PUSHI 51
  PUSHI 1
  STGX taken
n51:
  LDG n   ; n > k1 (1.5) is false -> jumps
  PUSHK 1
  JNGTF t52
  JMP n52
t52:
  PUSHI 52
  PUSHI 1
  STGX taken
n52:
  LDG n   ; n >= k1 (1.5) is false -> jumps
  PUSHK 1
  JNGEF t53
  JMP n53
t53:
  PUSHI 53
  PUSHI 1
  STGX taken
n53:
  LDG n   ; n == k2 (4.0) is false -> jumps
  PUSHK 2
  JNEQF t54
  JMP n54
t54:
  PUSHI 54
  PUSHI 1
  STGX taken
n54:
  LDG n   ; n != k2 (4.0) is true -> falls through
  PUSHK 2
  JNNEF t55
  JMP n55
t55:
  PUSHI 55
  PUSHI 1
  STGX taken
n55:
  LDG n   ; n < k2 (4.0) is false -> jumps
  PUSHK 2
  JNLTF t56
  JMP n56
t56:
  PUSHI 56
  PUSHI 1
  STGX taken
n56:
  LDG n   ; n <= k2 (4.0) is false -> jumps
  PUSHK 2
  JNLEF t57
  JMP n57
t57:
  PUSHI 57
  PUSHI 1
  STGX taken
n57:
  LDG n   ; n > k2 (4.0) is false -> jumps
  PUSHK 2
  JNGTF t58
  JMP n58
t58:
  PUSHI 58
  PUSHI 1
  STGX taken
n58:
  LDG n   ; n >= k2 (4.0) is false -> jumps
  PUSHK 2
  JNGEF t59
  JMP n59
t59:
  PUSHI 59
  PUSHI 1
  STGX taken
n59:
  LDG f   ; f == f is true -> falls through
  LDG f
  JNEQF t60
  JMP n60
t60:
  PUSHI 60
  PUSHI 1
  STGX taken
n60:
  LDG f   ; f != f is false -> jumps
  LDG f
  JNNEF t61
  JMP n61
t61:
  PUSHI 61
  PUSHI 1
  STGX taken
n61:
  LDG f   ; f < f is false -> jumps
  LDG f
  JNLTF t62
  JMP n62
t62:
  PUSHI 62
  PUSHI 1
  STGX taken
n62:
  LDG f   ; f <= f is true -> falls through
  LDG f
  JNLEF t63
  JMP n63
t63:
  PUSHI 63
  PUSHI 1
  STGX taken
n63:
  LDG f   ; f > f is false -> jumps
  LDG f
  JNGTF t64
  JMP n64
t64:
  PUSHI 64
  PUSHI 1
  STGX taken
n64:
  LDG f   ; f >= f is true -> falls through
  LDG f
  JNGEF t65
  JMP n65
t65:
  PUSHI 65
  PUSHI 1
  STGX taken
n65:
  LDG f   ; f == h (4.0) is false -> jumps
  LDG h
  JNEQF t66
  JMP n66
t66:
  PUSHI 66
  PUSHI 1
  STGX taken
n66:
  LDG f   ; f != h (4.0) is true -> falls through
  LDG h
  JNNEF t67
  JMP n67
t67:
  PUSHI 67
  PUSHI 1
  STGX taken
n67:
  LDG f   ; f < h (4.0) is true -> falls through
  LDG h
  JNLTF t68
  JMP n68
t68:
  PUSHI 68
  PUSHI 1
  STGX taken
n68:
  LDG f   ; f <= h (4.0) is true -> falls through
  LDG h
  JNLEF t69
  JMP n69
t69:
  PUSHI 69
  PUSHI 1
  STGX taken
n69:
  LDG f   ; f > h (4.0) is false -> jumps
  LDG h
  JNGTF t70
  JMP n70
t70:
  PUSHI 70
  PUSHI 1
  STGX taken
n70:
  LDG f   ; f >= h (4.0) is false -> jumps
  LDG h
  JNGEF t71
  JMP n71
t71:
  PUSHI 71
  PUSHI 1
  STGX taken
n71:
  LDG n   ; n == f is false -> jumps
  LDG f
  JNEQF t72
  JMP n72
t72:
  PUSHI 72
  PUSHI 1
  STGX taken
n72:
  LDG n   ; n != f is true -> falls through
  LDG f
  JNNEF t73
  JMP n73
t73:
  PUSHI 73
  PUSHI 1
  STGX taken
n73:
  LDG n   ; n < f is false -> jumps
  LDG f
  JNLTF t74
  JMP n74
t74:
  PUSHI 74
  PUSHI 1
  STGX taken
n74:
  LDG n   ; n <= f is false -> jumps
  LDG f
  JNLEF t75
  JMP n75
t75:
  PUSHI 75
  PUSHI 1
  STGX taken
n75:
  LDG n   ; n > f is false -> jumps
  LDG f
  JNGTF t76
  JMP n76
t76:
  PUSHI 76
  PUSHI 1
  STGX taken
n76:
  LDG n   ; n >= f is false -> jumps
  LDG f
  JNGEF t77
  JMP n77
t77:
  PUSHI 77
  PUSHI 1
  STGX taken
n77:
  LDG n   ; n == h (4.0) is false -> jumps
  LDG h
  JNEQF t78
  JMP n78
t78:
  PUSHI 78
  PUSHI 1
  STGX taken
n78:
  LDG n   ; n != h (4.0) is true -> falls through
  LDG h
  JNNEF t79
  JMP n79
t79:
  PUSHI 79
  PUSHI 1
  STGX taken
n79:
  LDG n   ; n < h (4.0) is false -> jumps
  LDG h
  JNLTF t80
  JMP n80
t80:
  PUSHI 80
  PUSHI 1
  STGX taken
n80:
  LDG n   ; n <= h (4.0) is false -> jumps
  LDG h
  JNLEF t81
  JMP n81
t81:
  PUSHI 81
  PUSHI 1
  STGX taken
n81:
  LDG n   ; n > h (4.0) is false -> jumps
  LDG h
  JNGTF t82
  JMP n82
t82:
  PUSHI 82
  PUSHI 1
  STGX taken
n82:
  LDG n   ; n >= h (4.0) is false -> jumps
  LDG h
  JNGEF t83
  JMP n83
t83:
  PUSHI 83
  PUSHI 1
  STGX taken
n83:
  RET
; expect taken[0] = 0
; expect taken[1] = 1
; expect taken[2] = 1
; expect taken[3] = 1
; expect taken[4] = 0
; expect taken[5] = 0
; expect taken[6] = 1
; expect taken[7] = 0
; expect taken[8] = 0
; expect taken[9] = 1
; expect taken[10] = 0
; expect taken[11] = 1
; expect taken[12] = 0
; expect taken[13] = 1
; expect taken[14] = 0
; expect taken[15] = 0
; expect taken[16] = 1
; expect taken[17] = 1
; expect taken[18] = 0
; expect taken[19] = 1
; expect taken[20] = 1
; expect taken[21] = 1
; expect taken[22] = 0
; expect taken[23] = 0
; expect taken[24] = 1
; expect taken[25] = 0
; expect taken[26] = 0
; expect taken[27] = 1
; expect taken[28] = 0
; expect taken[29] = 1
; expect taken[30] = 0
; expect taken[31] = 1
; expect taken[32] = 0
; expect taken[33] = 0
; expect taken[34] = 1
; expect taken[35] = 1
; expect taken[36] = 0
; expect taken[37] = 1
; expect taken[38] = 1
; expect taken[39] = 0
; expect taken[40] = 1
; expect taken[41] = 0
; expect taken[42] = 1
; expect taken[43] = 0
; expect taken[44] = 0
; expect taken[45] = 0
; expect taken[46] = 1
; expect taken[47] = 1
; expect taken[48] = 1
; expect taken[49] = 0
; expect taken[50] = 1
; expect taken[51] = 1
; expect taken[52] = 1
; expect taken[53] = 1
; expect taken[54] = 1
; expect taken[55] = 0
; expect taken[56] = 1
; expect taken[57] = 1
; expect taken[58] = 1
; expect taken[59] = 1
; expect taken[60] = 0
; expect taken[61] = 1
; expect taken[62] = 1
; expect taken[63] = 0
; expect taken[64] = 1
; expect taken[65] = 0
; expect taken[66] = 1
; expect taken[67] = 0
; expect taken[68] = 0
; expect taken[69] = 0
; expect taken[70] = 1
; expect taken[71] = 1
; expect taken[72] = 1
; expect taken[73] = 0
; expect taken[74] = 1
; expect taken[75] = 1
; expect taken[76] = 1
; expect taken[77] = 1
; expect taken[78] = 1
; expect taken[79] = 0
; expect taken[80] = 1
; expect taken[81] = 1
; expect taken[82] = 1
; expect taken[83] = 1
; expect end: finished
