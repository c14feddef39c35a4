# SPDX-License-Identifier: Apache-2.0
# kestrel-sim checks that need more than one command or read a file the
# command wrote. -DSIM=<kestrel-sim> -DOUT=<scratch dir> -DCHECK=<name>.
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})

if(CHECK STREQUAL "replay_wrong_kind")
  # A PCL stream replayed with a radar filter: an error naming both kinds
  # and a non-zero exit, not an empty run with exit 0.
  execute_process(COMMAND ${SIM} generate --scenario pcl002 --seed 3 --out ${OUT}/pcl.kstr RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "generate --scenario pcl002 failed (${rc})")
  endif()
  execute_process(COMMAND ${SIM} replay --stream ${OUT}/pcl.kstr --no-plots --out ${OUT}/replay
                  RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_VARIABLE out)
  if(rc EQUAL 0)
    message(FATAL_ERROR "replay of a PCL stream with ekf-ca exited 0:\n${out}${err}")
  endif()
  if(NOT err MATCHES "frames are PCL frames; filter 'ekf-ca' takes radar frames")
    message(FATAL_ERROR "replay of a PCL stream did not name the kinds:\n${err}")
  endif()
  if(EXISTS ${OUT}/replay/ekf-ca_tracks.csv)
    message(FATAL_ERROR "replay of a PCL stream wrote a track CSV")
  endif()
elseif(CHECK STREQUAL "suite_report")
  # The main job at tiny run counts: every part runs and report.md holds the
  # table of each paper's system.
  execute_process(COMMAND ${SIM} suite --runs 2 --mc-runs 2 --jobs 2 --no-plots --out ${OUT}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "suite failed (${rc}):\n${out}${err}")
  endif()
  file(READ ${OUT}/report.md report)
  foreach(expected
      "## Paper 000: adaptive EKF on manoeuvring radar targets \\(S1, S2\\)"
      "\\| s1 \\| EKF-CA \\(double\\), qj 1.6 \\| 2 \\|"
      "\\| s2 \\| EKF-CA \\(double\\), qj 160 \\| 2 \\|"
      "\\| s2 \\| R2-AEKF default mode"
      "\\| s1 \\| IMM CV/CA/CT \\(double\\)"
      "## Paper 001: .*\\| 0.01 \\| 0.1 \\| 0.01 \\|"
      "## Paper 002: .*2 runs of pcl002"
      "## Paper 003: .*2 runs of uw003")
    if(NOT report MATCHES "${expected}")
      message(FATAL_ERROR "report.md lacks '${expected}':\n${report}")
    endif()
  endforeach()
  if(report MATCHES "!\\[")
    message(FATAL_ERROR "report.md links a figure although --no-plots drew none")
  endif()
  foreach(f s1/ekf-ca-qj160_tracks.csv s2/r2aekf_runs.csv summary.json mc001/mc001_table.md
            pcl002/pcl_summary.json uw003/uw_summary.json)
    if(NOT EXISTS ${OUT}/${f})
      message(FATAL_ERROR "suite did not write ${f}")
    endif()
  endforeach()
elseif(CHECK STREQUAL "config_set")
  # --config, --set and a flag of its own, layered: the flag wins over --set,
  # which wins over the file; summary.json echoes what the run used. A value
  # out of range is an error naming it, and nothing is run.
  file(WRITE ${OUT}/config.json "{\"qj\": 16, \"confirm_m\": 3, \"confirm_n\": 4, \"gate_probability\": 0.99}")
  execute_process(COMMAND ${SIM} run --scenario s1 --runs 1 --no-plots --config ${OUT}/config.json
                          --set confirm_n=5 --qj 50 --out ${OUT}/run
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "run with --config and --set failed (${rc}):\n${out}${err}")
  endif()
  file(READ ${OUT}/run/summary.json summary)
  foreach(pair "qj=50" "confirm_m=3" "confirm_n=5" "gate_probability=0.99" "max_coast_misses=5")
    string(REPLACE "=" ";" kv ${pair})
    list(GET kv 0 key)
    list(GET kv 1 want)
    string(JSON got GET ${summary} results s1 ekf-ca parameters ${key})
    if(NOT got EQUAL want)
      message(FATAL_ERROR "summary.json parameters.${key} is ${got}, expected ${want}")
    endif()
  endforeach()
  execute_process(COMMAND ${SIM} run --scenario s1 --runs 1 --no-plots --set confirm_m=9 --out ${OUT}/bad
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(rc EQUAL 0 OR NOT err MATCHES "--set confirm_m=9: out of range")
    message(FATAL_ERROR "run --set confirm_m=9 was not refused by name (${rc}):\n${out}${err}")
  endif()
  if(EXISTS ${OUT}/bad/summary.json)
    message(FATAL_ERROR "run --set confirm_m=9 wrote a summary")
  endif()
else()
  message(FATAL_ERROR "unknown CHECK '${CHECK}'")
endif()
