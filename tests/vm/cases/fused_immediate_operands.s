; The int an expression left on top with an immediate: a mask (`(x + y) & 65535`, ST's and
; PDL's 16-bit counters and status words), a sum and a difference (`x * y + 1`, `x * y - 7`), a
; shift (`(x + y) >> 4`), fused at load into ANDIK, ADDIK (a difference too: the compile-time
; pass writes `- 7` as `+ -7`) and SHRIK; and a local set to an
; immediate (STLI). x = 70000, y = 3: 70003 & 65535 = 70003 - 65536 = 4467; 210000 + 1;
; 210000 - 7; 2^31 - 1 plus 0 plus 1 wraps to -2^31, -2^31 plus 0 minus 1 to 2^31 - 1; 0x1234 &
; -256 (0x...FF00) = 0x1200 = 4608; 70003 >> 4 = 4375 (70003 = 16 * 4375 + 3); -70003 >> 4 =
; -4376 (arithmetic: toward minus infinity); the local set to -5, then stored.
.const int 2147483647
.global int "x" 1
.global int "y" 1
.global int "big" 1
.global int "zero" 1
.global int "masked" 1
.global int "plus" 1
.global int "wrapped" 1
.global int "high" 1
.global int "minus" 1
.global int "unwrapped" 1
.global int "shifted" 1
.global int "negative_shifted" 1
.global int "local_set" 1
.routine function "main" in=0 out=0 entry=main
.local int "k"
main:
  PUSHI 70000
  STG x
  PUSHI 3
  STG y
  PUSHK 0
  STG big
  LDG x
  LDG y
  ADDI
  PUSHI 65535
  ANDI
  STG masked       ; (x + y) & 65535 (ANDIK)
  LDG x
  LDG y
  MULI
  PUSHI 1
  ADDI
  STG plus         ; x * y + 1 (ADDIK)
  LDG big
  LDG zero
  ADDI
  PUSHI 1
  ADDI
  STG wrapped      ; (2^31 - 1 + 0) + 1 wraps (ADDIK)
  PUSHI 4660
  PUSHI -256
  ANDI
  STG high         ; 0x1234 & -256: a negative immediate is sign-extended (ANDIK)
  LDG x
  LDG y
  MULI
  PUSHI -7
  ADDI
  STG minus        ; x * y - 7, as the compile-time pass writes it (ADDIK)
  LDG wrapped
  LDG zero
  ADDI
  PUSHI -1
  ADDI
  STG unwrapped    ; (-2^31 + 0) - 1 wraps (ADDIK of -1)
  LDG x
  LDG y
  ADDI
  PUSHI 4
  SHRI
  STG shifted      ; (x + y) >> 4 (SHRIK)
  LDG zero
  LDG x
  LDG y
  ADDI
  SUBI
  PUSHI 4
  SHRI
  STG negative_shifted ; (0 - (x + y)) >> 4 (SHRIK)
  PUSHI -5
  STL 0            ; k = -5 (STLI)
  LDL 0
  STG local_set
  RET
; expect end: finished
; expect masked = 4467
; expect plus = 210001
; expect wrapped = -2147483648
; expect high = 4608
; expect minus = 209993
; expect unwrapped = 2147483647
; expect shifted = 4375
; expect negative_shifted = -4376
; expect local_set = -5
