; Run-time error Raised: RAISE with a code the list does not know (99) raises Raised, so a
; thread never stops with a code that has no meaning.
.global int "before" 1
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 1
  STG before
  RAISE 99
; expect end: error Raised
; expect before = 1
