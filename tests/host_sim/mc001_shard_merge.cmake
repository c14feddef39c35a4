# SPDX-License-Identifier: Apache-2.0
# MC-001 sharding (docs/filters.md): the table of a single run equals, byte for byte,
# the table merged from shards run with another thread count; merge refuses
# an incomplete set of shards. Run by CTest as
#   cmake -DSIM=<kestrel-sim> -DOUT=<dir> -P mc001_shard_merge.cmake
# A few runs per cell keep it to seconds; the CRPFs make every run distinct.
if(NOT SIM OR NOT OUT)
  message(FATAL_ERROR "usage: cmake -DSIM=<kestrel-sim> -DOUT=<dir> -P mc001_shard_merge.cmake")
endif()
set(runs 7)
file(REMOVE_RECURSE "${OUT}")

function(sim)
  execute_process(COMMAND "${SIM}" ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "kestrel-sim ${ARGN} failed (${rc}):\n${out}\n${err}")
  endif()
endfunction()

sim(montecarlo --campaign mc001 --runs ${runs} --jobs 2 --no-plots --no-progress --out "${OUT}/single")
foreach(k 1 2 3)
  sim(montecarlo --campaign mc001 --runs ${runs} --jobs 1 --shard ${k}/3 --no-plots --no-progress
      --out "${OUT}/shard-${k}")
endforeach()
# Shards given out of order: merge sorts them by their run ranges.
sim(merge "${OUT}/shard-3" "${OUT}/shard-1" "${OUT}/shard-2" --no-plots --out "${OUT}/merged")

foreach(f mc001_mse.csv mc001_table.md)
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files "${OUT}/single/${f}" "${OUT}/merged/${f}"
                  RESULT_VARIABLE differ)
  if(NOT differ EQUAL 0)
    message(FATAL_ERROR "${f}: merged shards differ from the single run")
  endif()
endforeach()

# A missing shard is an error, not a smaller table.
execute_process(COMMAND "${SIM}" merge "${OUT}/shard-1" "${OUT}/shard-3" --no-plots --out "${OUT}/incomplete"
                RESULT_VARIABLE rc OUTPUT_QUIET ERROR_QUIET)
if(rc EQUAL 0)
  message(FATAL_ERROR "merge accepted shards 1 and 3 of 3")
endif()
message(STATUS "single run and merged shards 1-3/3 give the same table; an incomplete merge is refused")
