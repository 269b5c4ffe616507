# Runs one uprog command line and checks how it ends: its exit code, a pattern its output
# (stdout and stderr together) must hold and one it must not.
#   cmake -DUPROG=path -DARGS="run|file.ehl" -DEXIT=1 -DMATCH=regex [-DREFUSE=regex] -P expect_run.cmake
string(REPLACE "|" ";" args "${ARGS}")
execute_process(COMMAND ${UPROG} ${args} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE out
                TIMEOUT 60)
message("${out}")
if(NOT code STREQUAL EXIT)
  message(FATAL_ERROR "exit code ${code}, expected ${EXIT}")
endif()
if(NOT out MATCHES "${MATCH}")
  message(FATAL_ERROR "the output does not hold: ${MATCH}")
endif()
if(NOT "${REFUSE}" STREQUAL "" AND out MATCHES "${REFUSE}")
  message(FATAL_ERROR "the output holds what it must not: ${REFUSE}")
endif()
