; A host call that answers kCommandEndSlice: the instruction completes and the slice ends
; after it, as at YIELD (Akribis' AWaitTime, ST's XREAD costing a slice). Command 4 of the test
; host does so on every call: each of the six host-call instructions ends a slice, and the
; seventh slice finishes.
.global int "got" 2
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 5
  CMDSET 4 2        ; register 2 = 5
  CMDGET 4 2
  STG got
  PUSHI 6
  PUSHI 8
  CMDSETX 4         ; register 6 = 8
  PUSHI 1
  PUSHI 6
  CMDGETX 4
  STGX got
  CMDRUN 4 0
  PUSHI 3
  PUSHI 7
  CMDRUNX 4 1       ; at index 3, with 7
  RET
; expect end: finished
; expect slices = 7
; expect got[0] = 5
; expect got[1] = 8
; expect runs = 2
; expect action index = 3
