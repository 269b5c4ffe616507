; Base code only (format 6), as it was written of the fused instructions named below before
; they left the stored format: the machine fuses it again at load (vm/fused.def), and the
; expectations are the same, so each fused handler is checked against its base code.
; UNTILCK, a wait on a command (`until (MS == 0)`): the thread yields in place until the
; command's value, as an int, compares with the immediate, then goes on. B packs the index
; (bits 0-7), the comparison (bits 8-11: 0 ==, 1 !=, 2 <, 3 <=, 4 >, 5 >=) and the immediate
; (bits 12-31, signed). Command 5 of the test host counts its reads (the n-th read gives n).
.global int "after" 1
.routine function "main" in=0 out=0 entry=main
main:
q_until_1:
  CMDGET 5 0
  PUSHI 4
  JGEI q_until_2
  YIELD
  JMP q_until_1
q_until_2:
  PUSHI 1
  STG after
  PUSHI 5
  CMDSET 4 2              ; register 2 = 5; command 4 ends the slice (4)
q_until_3:
  CMDGET 4 2
  PUSHI 5
  JEQI q_until_4
  YIELD
  JMP q_until_3
q_until_4:
  PUSHI 2
  STG after
q_until_5:
  CMDGET 5 0
  PUSHI -3
  JGTI q_until_6
  YIELD
  JMP q_until_5
q_until_6:
  RET                     ; (6)
; expect end: finished
; expect slices = 6
; expect counter reads = 5
; expect after = 2
