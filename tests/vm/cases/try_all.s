; TRYALL enters a try block as TRY does; it differs only for errors of event routines
; entered above it, which it catches too (machine_test.cpp, TryAllCatchesAnEventsError).
.global int "code" 1
.routine function "main" in=0 out=0 entry=main
main:
  TRYALL catch
  PUSHI 1
  PUSHI 0
  DIVI
  POP
  ENDTRY
  RET
catch:
  ERRCODE
  STG code
  RET
; expect end: finished
; expect code = 1
