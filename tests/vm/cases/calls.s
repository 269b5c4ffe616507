; Calls: inputs in locals, several outputs, nargout, recursion.
.global int "fib10" 1
.global int "q" 1
.global int "r" 1
.global int "wanted" 2
.routine function "main" in=0 out=0 entry=main
.routine function "fib" in=1 out=1 entry=fib
.local int "n"
.local int "f"
.routine function "divmod" in=2 out=2 entry=divmod
.local int "a"
.local int "b"
.local int "q"
.local int "r"
.routine function "outs" in=0 out=2 entry=outs
.local int "x"
.local int "y"
main:
  PUSHI 10
  CALL fib 1
  STG fib10
  PUSHI 17
  PUSHI 5
  CALL divmod 2
  STG r
  STG q
  CALL outs 0
  CALL outs 1
  POP
  PUSHI 0
  CALL outs 2
  POP
  POP
  LDG wanted
  STGX wanted       ; wanted[0] = wanted[0] as seen after the 2-output call
  RET
fib:
  LDL 0
  PUSHI 2
  CMPI 2
  JZ more
  LDL 0
  STL 1
  RET
more:
  LDL 0
  PUSHI 1
  SUBI
  CALL fib 1
  LDL 0
  PUSHI 2
  SUBI
  CALL fib 1
  ADDI
  STL 1
  RET
divmod:
  LDL 0
  LDL 1
  DIVI
  STL 2
  LDL 0
  LDL 1
  REMI
  STL 3
  RET
outs:
  NARGOUT
  STG wanted        ; the last call asked for 2
  RET
; expect end: finished
; expect fib10 = 55
; expect q = 3
; expect r = 2
; expect wanted[0] = 2
