; A counted loop as ST's FOR is compiled (inverted: the test before the loop and again after the
; step, the bound in a local): the step and the bottom test are base code that the machine fuses
; at load into INCGJLEGL for <= (step +1), a FOR counting up; the others stay base code: >=
; (step -2, counting down), != (step +3), and bottom tests only (as ne's) for
; < (step +2), > (step -3) and == (step +1), so that every relation runs. up: 1..4 is 4 passes,
; ending at 5; down: 10, 8, 6, 4 is 4 passes, ending at 2; ne: 0, 3, 6 is 3 passes, ending at 9;
; none: 7 > 4, no pass, 7 stays; lt: 0, 2, 4 while < 5 is 3 passes, ending at 6; gt: 10, 7, 4
; while > 2 is 3 passes, ending at 1; eq: 4, 5 while == 5 is 2 passes, ending at 6.
.global int "up" 1
.global int "up_passes" 1
.global int "down" 1
.global int "down_passes" 1
.global int "ne" 1
.global int "ne_passes" 1
.global int "none" 1
.global int "none_passes" 1
.global int "lt" 1
.global int "lt_passes" 1
.global int "gt" 1
.global int "gt_passes" 1
.global int "eq" 1
.global int "eq_passes" 1
.routine function "main" in=0 out=0 entry=main
.local int "bound"
main:
  PUSHI 1
  STG up
  PUSHI 4
  STL 0  ; bound
  LDG up
  LDL 0  ; bound
  JLEI up_body
  JMP up_done
up_body:
  LDG up_passes
  PUSHI 1
  ADDI
  STG up_passes
  LDG up
  PUSHI 1
  ADDI
  STG up
  LDG up
  LDL 0  ; bound
  JLEI up_body
up_done:
  PUSHI 10
  STG down
  PUSHI 3
  STL 0  ; bound
  LDG down
  LDL 0  ; bound
  JGEI down_body
  JMP down_done
down_body:
  LDG down_passes
  PUSHI 1
  ADDI
  STG down_passes
  LDG down
  PUSHI -2
  ADDI
  STG down
  LDG down
  LDL 0  ; bound
  JGEI down_body
down_done:
  PUSHI 9
  STL 0  ; bound
ne_body:
  LDG ne_passes
  PUSHI 1
  ADDI
  STG ne_passes
  LDG ne
  PUSHI 3
  ADDI
  STG ne
  LDG ne
  LDL 0  ; bound
  JNEI ne_body
  PUSHI 7
  STG none
  PUSHI 4
  STL 0  ; bound
  LDG none
  LDL 0  ; bound
  JLEI none_body
  JMP none_done
none_body:
  LDG none_passes
  PUSHI 1
  ADDI
  STG none_passes
  LDG none
  PUSHI 1
  ADDI
  STG none
  LDG none
  LDL 0  ; bound
  JLEI none_body
none_done:
  PUSHI 0
  STG lt
  PUSHI 5
  STL 0  ; bound
lt_body:
  LDG lt_passes
  PUSHI 1
  ADDI
  STG lt_passes
  LDG lt
  PUSHI 2
  ADDI
  STG lt
  LDG lt
  LDL 0  ; bound
  JLTI lt_body
  PUSHI 10
  STG gt
  PUSHI 2
  STL 0  ; bound
gt_body:
  LDG gt_passes
  PUSHI 1
  ADDI
  STG gt_passes
  LDG gt
  PUSHI -3
  ADDI
  STG gt
  LDG gt
  LDL 0  ; bound
  JGTI gt_body
  PUSHI 4
  STG eq
  PUSHI 5
  STL 0  ; bound
eq_body:
  LDG eq_passes
  PUSHI 1
  ADDI
  STG eq_passes
  LDG eq
  PUSHI 1
  ADDI
  STG eq
  LDG eq
  LDL 0  ; bound
  JEQI eq_body
  RET
; expect end: finished
; expect up = 5
; expect up_passes = 4
; expect down = 2
; expect down_passes = 4
; expect ne = 9
; expect ne_passes = 3
; expect none = 7
; expect none_passes = 0
; expect lt = 6
; expect lt_passes = 3
; expect gt = 1
; expect gt_passes = 3
; expect eq = 6
; expect eq_passes = 2
