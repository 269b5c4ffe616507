; an address's range test (JULTK) reads the int on top and keeps it: on an empty stack it has
; nothing to read
.routine function "main" in=0 out=0 entry=main
main:
  JULTK done 4
done:
  RET
; expect verify: StackUnderflow
