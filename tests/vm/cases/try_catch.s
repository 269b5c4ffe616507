; try/catch restores the stacks and runs the catch block, also from inside a call; ERRCODE
; reads the error; ENDTRY leaves a block that did not fail.
.global int "caught" 1
.global int "code" 1
.global int "after" 1
.global int "clean" 1
.routine function "main" in=0 out=0 entry=main
.routine function "divide" in=2 out=1 entry=divide
.local int "a"
.local int "b"
.local int "q"
main:
  TRY ok_catch
  PUSHI 1
  STG clean
  ENDTRY
  JMP second
ok_catch:
  PUSHI 99
  STG clean         ; never reached
second:
  PUSHI 7           ; a value left below the try: the catch must see it again
  TRY handler
  PUSHI 8
  PUSHI 0
  CALL divide 1     ; fails inside the call
  POP
  ENDTRY
  POP
  JMP end
handler:
  STG after         ; the 7 pushed before the try
  PUSHI 1
  STG caught
  ERRCODE
  STG code
end:
  RET
divide:
  LDL 0
  LDL 1
  DIVI
  STL 2
  RET
; expect end: finished
; expect clean = 1
; expect caught = 1
; expect code = 1
; expect after = 7
