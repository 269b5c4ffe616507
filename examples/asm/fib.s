; Recursive Fibonacci on the bare VM: main computes fib(20) into the global `result`.
; Run it: build/bin/uprog exec examples/asm/fib.s   (expects result = 6765)
.source "fib.s"
.global int "result" 1
.routine function "main" in=0 out=0 entry=main
.routine function "fib" in=1 out=1 entry=fib
.local int "n"
.local int "r"

main:
  PUSHI 20
  CALL fib 1          ; fib(20), one output wanted
  STG result
  RET
fib:
  LDL 0
  PUSHI 2
  CMPI 2
  JZ recurse          ; n >= 2: recurse
  LDL 0
  STL 1               ; r = n
  RET
recurse:
  LDL 0
  PUSHI 1
  SUBI
  CALL fib 1
  LDL 0
  PUSHI 2
  SUBI
  CALL fib 1
  ADDI
  STL 1               ; r = fib(n-1) + fib(n-2)
  RET
