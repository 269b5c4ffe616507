; A procedure's result through its pointer parameter, as PDL's `*r=n;` ends once the pointer's
; tests have left it on top (fused_frame_pointer.s): a frame word loaded and stored at that
; address, base code that the machine fuses at load into LDMLKSTM (vm/fused.def). The data
; memory is the globals' words: `mem` is words 0..7, `frame` words 8..9, `under` word 10, and
; fp = 8, so fp + 1 is frame[1] = 41. 77 waits under the pointer and is stored in `under` after
; the store: the store takes the pointer and leaves 77. The second pointer, 11, is one past the
; memory's 11 words: BadAddress, nothing stored (`under` keeps 77).
.global int "mem" 8
.global int "frame" 2
.global int "under" 1
.routine function "main" in=0 out=0 entry=main
.local int "fp"
main:
  PUSHI 8
  STL 0
  PUSHI 1
  PUSHI 41
  STGX frame       ; frame[1] = 41
  PUSHI 77
  PUSHI 5          ; the pointer: mem[5]
  LDL 0
  PUSHI 1
  ADDI
  LDM
  STM              ; mem[5] = frame[1] (LDMLKSTM)
  STG under        ; 77
  PUSHI 11
  LDL 0
  PUSHI 1
  ADDI
  LDM
  STM              ; mem[11]: past the data memory
  RET
; expect end: error BadAddress
; expect mem[4] = 0
; expect mem[5] = 41
; expect mem[6] = 0
; expect under = 77
