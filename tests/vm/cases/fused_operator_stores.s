; Assignments of one int operator with an immediate, of a global and of a local (`r3=i%3;`,
; `v=i*7919;`, `n%=7;`): base code the machine fuses at load into ADDGKS, DIVGKS, REMGKS and
; DIVLKS (vm/fused.def; the other operators stay base code, as does a difference written with
; SUBI: the compile-time pass writes `- 20` as `+ -20`, ADDGKS and ADDGK); and REMGK and ADDGK,
; a remainder and a difference pushed. Each operator as opcodes.def defines its base
; instruction: + - * wrap, / truncates toward zero (INT32_MIN / -1 saturates: support/arith.h),
; % takes the dividend's sign.
; x = 17, y = -17, big = 2147483647 (k0), least = -2147483648 (k1).
.global int "x" 1
.global int "y" 1
.global int "big" 1
.global int "least" 1
.global int "gadd" 1
.global int "gsub" 1
.global int "gmul" 1
.global int "gdiv" 1
.global int "grem" 1
.global int "gdivneg" 1
.global int "gremneg" 1
.global int "gwrapadd" 1
.global int "gwrapmul" 1
.global int "gsat" 1
.global int "inplace" 1
.global int "pushed" 1
.global int "pushedsub" 1
.global int "ladd" 1
.global int "lsub" 1
.global int "lmul" 1
.global int "ldiv" 1
.global int "lrem" 1
.const int 2147483647    ; k0
.const int -2147483648   ; k1
.routine function "main" in=0 out=0 entry=main
.local int "a"
.local int "b"
main:
  PUSHI 17
  STG x
  PUSHI -17
  STG y
  PUSHK 0
  STG big
  PUSHK 1
  STG least
  LDG x
  PUSHI 5
  ADDI
  STG gadd       ; 17 + 5 = 22
  LDG x
  PUSHI -20
  ADDI
  STG gsub       ; 17 - 20 = -3, as the compile-time pass writes it (ADDGKS)
  LDG x
  PUSHI -3
  MULI
  STG gmul       ; 17 * -3 = -51
  LDG x
  PUSHI 5
  DIVI
  STG gdiv       ; 17 / 5 = 3
  LDG x
  PUSHI 5
  REMI
  STG grem       ; 17 % 5 = 2
  LDG y
  PUSHI 5
  DIVI
  STG gdivneg    ; -17 / 5 = -3 (toward zero)
  LDG y
  PUSHI 5
  REMI
  STG gremneg    ; -17 % 5 = -2
  LDG big
  PUSHI 1
  ADDI
  STG gwrapadd   ; 2147483647 + 1 wraps to -2147483648
  LDG big
  PUSHI 2
  MULI
  STG gwrapmul   ; 2147483647 * 2 wraps to -2
  LDG least
  PUSHI -1
  DIVI
  STG gsat       ; -2147483648 / -1 saturates to 2147483647
  PUSHI 100
  STG inplace
  LDG inplace
  PUSHI 7
  REMI
  STG inplace    ; 100 % 7 = 2, in place
  LDG x
  PUSHI 5
  REMI
  PUSHI 1
  ADDI
  STG pushed     ; 17 % 5 + 1 = 3: a remainder pushed (REMGK), no assignment of one operator
  LDG x
  PUSHI -20
  ADDI
  PUSHI 2
  MULI
  STG pushedsub  ; (17 - 20) * 2 = -6: a difference pushed (ADDGK, PUP's `Arr[(I - 1) * 2]`)
  PUSHI 17
  STL 0
  LDL 0
  PUSHI 5
  ADDI
  STL 1
  LDL 1
  STG ladd       ; 22
  LDL 0
  PUSHI 20
  SUBI
  STL 1
  LDL 1
  STG lsub       ; -3 (SUBI as written: base code)
  LDL 0
  PUSHI -3
  MULI
  STL 1
  LDL 1
  STG lmul       ; -51
  LDL 0
  PUSHI 5
  DIVI
  STL 1
  LDL 1
  STG ldiv       ; 3
  LDL 0
  PUSHI 5
  REMI
  STL 0
  LDL 0
  STG lrem       ; 2, in place
  RET
; expect end: finished
; expect gadd = 22
; expect gsub = -3
; expect gmul = -51
; expect gdiv = 3
; expect grem = 2
; expect gdivneg = -3
; expect gremneg = -2
; expect gwrapadd = -2147483648
; expect gwrapmul = -2
; expect gsat = 2147483647
; expect inplace = 2
; expect pushed = 3
; expect pushedsub = -6
; expect ladd = 22
; expect lsub = -3
; expect lmul = -51
; expect ldiv = 3
; expect lrem = 2
