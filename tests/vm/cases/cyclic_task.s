; An image as an ST compiler might make it: its dialect, and task records for the scheduler
; (the VM runs whatever routine it is started on; the records are the firmware's). "main"
; does what the scheduler would at reset and at the first 62.5 us tick: PLCINIT, then PLC62,
; which adds its period in ns to a DLONG (two words, low first) about to cross 2^32.
.dialect "st"
.global int "NANOS" 2
.routine function "main" in=0 out=0 entry=main
.routine task "PLCINIT" in=0 out=0 entry=init
.routine task "PLC62" in=0 out=0 entry=plc62
.task 1 number=0 period_ns=0 priority=0 start_at_reset=1
.task "PLC62" number=62 period_ns=62500 priority=256 start_at_reset=0
main:
  CALL PLCINIT 0
  CALL PLC62 0
  RET
init:
  PUSHI 0
  PUSHI -10000
  STGX NANOS
  RET
plc62:
  PUSHI 0
  LDGX NANOS
  PUSHI 1
  LDGX NANOS
  PUSHI 62500
  I2W
  ADDW
  PUSHI 1
  SWAP
  STGX NANOS
  PUSHI 0
  SWAP
  STGX NANOS
  RET
; expect end: finished
; expect NANOS[0] = 52500
; expect NANOS[1] = 1
