# SPDX-License-Identifier: Apache-2.0
# cmake -DCXX=<compiler> -DFLAGS=<list> -DSRC=<file> -DOUT=<exe> [-DRUNNER=<emulator>]
#   -P build_and_run.cmake
# Builds the golden-hash program with FLAGS and runs it (under RUNNER, e.g.
# qemu-arm, when given); fails if either step fails (the program exits
# non-zero when a hash differs from the checked-in constant or an overflow
# was counted).
execute_process(COMMAND ${CXX} ${FLAGS} ${SRC} -o ${OUT} RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "build failed (${CXX} ${FLAGS}):\n${err}")
endif()
execute_process(COMMAND ${RUNNER} ${OUT} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "golden hash mismatch with flags ${FLAGS}")
endif()
