; A quotient's 16-bit check, as ST's `/` and MOD make it (the manual's 16-bit division): the
; value compared with its low 16 bits sign-extended, Overflow unless equal; base code that the
; machine fuses at load into CHKS16 (vm/fused.def) where the RAISE is Overflow's (16). The check
; pops what it tests: a DUP before it keeps the value (`/`), none consumes it (MOD's quotient).
; -32768 fits and is kept; 32767 fits and is popped, so `after` takes the 5 below it; a RAISE of
; another code is not fused and stays base code that raises nothing when the value fits; 32768
; does not fit: Overflow, and `reached` stays 0.
.global int "kept" 1
.global int "after" 1
.global int "other" 1
.global int "reached" 1
.routine function "main" in=0 out=0 entry=main
main:
  PUSHI 5
  PUSHI -32768
  DUP
  DUP
  SEXT 16
  JEQI fits
  RAISE 16
fits:
  STG kept
  PUSHI 32767
  DUP
  SEXT 16
  JEQI popped
  RAISE 16
popped:
  STG after
  PUSHI 9
  DUP
  DUP
  SEXT 16
  JEQI other_code
  RAISE 15
other_code:
  STG other
  PUSHI 32768
  DUP
  SEXT 16
  JEQI beyond
  RAISE 16
beyond:
  PUSHI 1
  STG reached
  RET
; expect end: error Overflow
; expect kept = -32768
; expect after = 5
; expect other = 9
; expect reached = 0
