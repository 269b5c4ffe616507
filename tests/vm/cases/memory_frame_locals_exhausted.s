; CALLFEOL past the thread's 1024 local slots is LocalsExhausted, and stores nothing: main has 2
; locals and proc 64, so 15 procs fill 962 slots and the 16th call is refused (before 30 frames
; and the frame's limit). Each frame is 3 words, its one argument (7) into word 2: call j's frame
; starts at word 3(j - 1), so proc 15's argument is mem[44], the refused call's mem[47].
.global int "mem" 100
.global int "depth" 1
.routine function "main" in=0 out=0 entry=main
.local int "sp"
.local int "limit"
.routine function "proc" in=3 out=0 entry=proc
.local int "sp"
.local int "limit"
.local int "fp"
.local int "v0"
.local int "v1"
.local int "v2"
.local int "v3"
.local int "v4"
.local int "v5"
.local int "v6"
.local int "v7"
.local int "v8"
.local int "v9"
.local int "v10"
.local int "v11"
.local int "v12"
.local int "v13"
.local int "v14"
.local int "v15"
.local int "v16"
.local int "v17"
.local int "v18"
.local int "v19"
.local int "v20"
.local int "v21"
.local int "v22"
.local int "v23"
.local int "v24"
.local int "v25"
.local int "v26"
.local int "v27"
.local int "v28"
.local int "v29"
.local int "v30"
.local int "v31"
.local int "v32"
.local int "v33"
.local int "v34"
.local int "v35"
.local int "v36"
.local int "v37"
.local int "v38"
.local int "v39"
.local int "v40"
.local int "v41"
.local int "v42"
.local int "v43"
.local int "v44"
.local int "v45"
.local int "v46"
.local int "v47"
.local int "v48"
.local int "v49"
.local int "v50"
.local int "v51"
.local int "v52"
.local int "v53"
.local int "v54"
.local int "v55"
.local int "v56"
.local int "v57"
.local int "v58"
.local int "v59"
.local int "v60"
main:
  PUSHI 100
  STL 1              ; limit = 100, sp = 0
  PUSHI 47
  PUSHI 99
  STM                ; mem[47] = 99
  PUSHI 7
  CALLFEOL proc 2101251   ; 3 words, 1 argument into word 2
  RET
proc:
  LDG depth
  PUSHI 1
  ADDI
  STG depth
  PUSHI 7
  CALLFEOL proc 2101251
  RET
; expect end: error LocalsExhausted
; expect depth = 15
; expect mem[44] = 7
; expect mem[47] = 99
