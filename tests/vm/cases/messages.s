; Messages to the host: MSG A B pops B values and hands text A of the image and the raw words
; to Host::message (PDL's printl, ST's PRINTF). The VM formats nothing.
.text "x=%d y=%d"
.text "done"
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 42
  PUSHI -3
  MSG 0 2
  MSG 1 0
  RET
; expect end: finished
; expect messages = 2
; expect message 0 = 0 42 -3
; expect message 1 = 1
