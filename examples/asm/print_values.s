; Messages on the bare VM: MSG sends a text of the image with raw argument words to the host,
; which formats them (support/format_message.h); `uprog exec` prints each on a line.
; Run it: build/bin/uprog exec examples/asm/print_values.s
;   prints "fib(20) = 6765, 0x1a6d" and "pi is about 3.14159"
.source "print_values.s"
.text "fib(%d) = %d, 0x%x"
.text "pi is about %g"
.const float 3.14159
.routine function "main" in=0 out=0 entry=main

main:
  PUSHI 20
  PUSHI 6765
  PUSHI 6765
  MSG 0 3
  PUSHK 0
  MSG 1 1
  RET
