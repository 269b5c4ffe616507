; An index past a window (LDGW's B: elements 1..3 of `arr`, indexed 1 to 3) is IndexOutOfRange,
; although `arr` has an element there; the store before the failing one is made, that after not.
.global int "arr" 5
.global int "before" 1
.global int "after" 1
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 7
  PUSHI 3
  STGW arr 196609
  PUSHI 1
  STG before
  PUSHI 4
  LDGW arr 196609
  STG after
  RET
; expect end: error IndexOutOfRange
; expect arr[3] = 7
; expect arr[4] = 0
; expect before = 1
; expect after = 0
