; The int an expression left on top with an immediate: a mask (`(x + y) & 65535`, ST's and
; PDL's 16-bit counters and status words) and a sum (`x * y + 1`), fused at load into ANDIK and
; ADDIK. x = 70000, y = 3: 70003 & 65535 = 70003 - 65536 = 4467; 210000 + 1; 2^31 - 1 plus 0
; plus 1 wraps to -2^31; 0x1234 & -256 (0x...FF00) = 0x1200 = 4608.
.const int 2147483647
.global int "x" 1
.global int "y" 1
.global int "big" 1
.global int "zero" 1
.global int "masked" 1
.global int "plus" 1
.global int "wrapped" 1
.global int "high" 1
.routine function "main" in=0 out=0 entry=main
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
  RET
; expect end: finished
; expect masked = 4467
; expect plus = 210001
; expect wrapped = -2147483648
; expect high = 4608
