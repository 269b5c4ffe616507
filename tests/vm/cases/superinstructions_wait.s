; UNTILCK, a wait on a command (`until (MS == 0)`): the thread yields in place until the
; command's value, as an int, compares with the immediate, then goes on. B packs the index
; (bits 0-7), the comparison (bits 8-11: 0 ==, 1 !=, 2 <, 3 <=, 4 >, 5 >=) and the immediate
; (bits 12-31, signed). Command 5 of the test host counts its reads (the n-th read gives n).
.global int "after" 1
.routine function "main" in=0 out=0 entry=main
main:
  UNTILCK 5 17664         ; until the counter >= 4: reads 1-4, one a slice (slices 1-4)
  PUSHI 1
  STG after
  PUSHI 5
  CMDSET 4 2              ; register 2 = 5; command 4 ends the slice (4)
  UNTILCK 4 20482         ; until register 2 == 5: met, and the read ends the slice (5)
  PUSHI 2
  STG after
  UNTILCK 5 -11264          ; until the counter > -3: read 5 is, at once
  RET                     ; (6)
; expect end: finished
; expect slices = 6
; expect counter reads = 5
; expect after = 2
