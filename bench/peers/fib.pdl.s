; uprog assembly
.source "bench/peers/fib.pdl"
.created 1796623200
.dialect "pdl"
.info "var result long 0 0 0"
.info "proc fib 1 119 6 2 n:l:0:1:2 r:l:1:1:3 a:l:0:1:4 b:l:0:1:5"
.info "rets"
.info "loops"
.const int -536870913  ; k0
.global int "result" 1  ; g0
.global int "(free)" 399  ; g1
.global int "(unused)" 3696  ; g2
.global int "(stack 1)" 256  ; g3
.global int "(unused)" 3840  ; g4
.global int "(stack 2)" 256  ; g5
.global int "(unused)" 3840  ; g6
.global int "(stack 3)" 256  ; g7
.routine function "(start)" in=4 out=0 entry=L0  ; r0
.local int "sp"
.local int "limit"
.local int "base"
.local int "fp"
.local int "ret"
.local int "goto"
.local int "s0"
.local int "s1"
.local int "s2"
.local int "s3"
.local int "s4"
.local int "s5"
.local int "s6"
.local int "s7"
.local int "s8"
.local int "s9"
.routine function "proc fib" in=4 out=0 entry=L1  ; r1
.local int "sp"
.local int "limit"
.local int "base"
.local int "fp"
.local int "ret"
.local int "goto"
.routine task "task 1" in=4 out=0 entry=L119  ; r2
.local int "sp"
.local int "limit"
.local int "base"
.local int "fp"
.local int "ret"
.local int "goto"
.local int "s0"
.local int "s1"
.local int "s2"
.local int "s3"
.local int "s4"
.local int "s5"
.local int "s6"
.local int "s7"
.local int "s8"
.local int "s9"
.task 2 number=1 period_ns=0 priority=0 start_at_reset=1  ; "task 1"

L0:
  JMP L119
.line "bench/peers/fib.pdl" 7
L1:
  LDL 3
  PUSHI 2
  ADDI
  LDM
  PUSHI 2
  JGEI.eol L41
.line "bench/peers/fib.pdl" 8
  LDL 3
  PUSHI 3
  ADDI
  LDM
  DUP
  PUSHI 400
  CMPU 2
  JNZ L35
  DUP
  LDL 2
  SUBI
  PUSHI 256
  CMPU 2
  JNZ L35
  PUSHK 0  ; -536870913
  ANDI
  DUP
  PUSHI 4096
  JGEI L31
  DUP
  PUSHI 400
  CMPU 2
  JNZ L35
L30:
  RAISE 15
L31:
  DUP
  PUSHI -12544
  ANDI
  JNZ L30
L35:
  LDL 3
  PUSHI 2
  ADDI
  LDM
  STM.eol
.line "bench/peers/fib.pdl" 9
  RETEOL
.line "bench/peers/fib.pdl" 11
L41:
  LDL 3
  PUSHI 2
  ADDI
  LDL 3
  PUSHI 2
  ADDI
  LDM
  PUSHI 1
  SUBI
  STM.eol
.line "bench/peers/fib.pdl" 12
  LDL 3
  PUSHI 2
  ADDI
  LDM
  LDL 3
  PUSHI 4
  ADDI
  CALLFEOL 1 2105350  ; proc fib
.line "bench/peers/fib.pdl" 13
  LDL 3
  PUSHI 2
  ADDI
  LDL 3
  PUSHI 2
  ADDI
  LDM
  PUSHI 1
  SUBI
  STM.eol
.line "bench/peers/fib.pdl" 14
  LDL 3
  PUSHI 2
  ADDI
  LDM
  LDL 3
  PUSHI 5
  ADDI
  CALLFEOL 1 2105350  ; proc fib
.line "bench/peers/fib.pdl" 15
  LDL 3
  PUSHI 3
  ADDI
  LDM
  DUP
  PUSHI 400
  CMPU 2
  JNZ L107
  DUP
  LDL 2
  SUBI
  PUSHI 256
  CMPU 2
  JNZ L107
  PUSHK 0  ; -536870913
  ANDI
  DUP
  PUSHI 4096
  JGEI L103
  DUP
  PUSHI 400
  CMPU 2
  JNZ L107
L102:
  RAISE 15
L103:
  DUP
  PUSHI -12544
  ANDI
  JNZ L102
L107:
  LDL 3
  PUSHI 4
  ADDI
  LDM
  LDL 3
  PUSHI 5
  ADDI
  LDM
  ADDI
  STM.eol
.line "bench/peers/fib.pdl" 16
  RETEOL
  RET
.line "bench/peers/fib.pdl" 18
L119:
  PUSHI 27
  PUSHI 0
  CALLFEOL 1 2105350  ; proc fib
.line "bench/peers/fib.pdl" 19
  EOL
  EXIT
