# SPDX-License-Identifier: Apache-2.0
# kestrel-sim checks that need more than one command or read a file the
# command wrote. -DSIM=<kestrel-sim> -DOUT=<scratch dir> -DCHECK=<name>.
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})

# Generate one stream of a PCL or sonar scenario into ${OUT}/NAME.kstr.
function(generate_stream scenario name)
  execute_process(COMMAND ${SIM} generate --scenario ${scenario} --seed 3 --out ${OUT}/${name}.kstr
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "generate --scenario ${scenario} failed (${rc}):\n${out}${err}")
  endif()
endfunction()

# Run `replay ARGN`, which must fail naming `pattern` on stderr and write no
# summary into ${OUT}/${dir}.
function(expect_replay_error dir pattern)
  execute_process(COMMAND ${SIM} replay ${ARGN} --no-plots --out ${OUT}/${dir}
                  RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_VARIABLE out)
  if(rc EQUAL 0)
    message(FATAL_ERROR "replay ${ARGN} exited 0:\n${out}${err}")
  endif()
  if(NOT err MATCHES "${pattern}")
    message(FATAL_ERROR "replay ${ARGN} did not say '${pattern}':\n${out}${err}")
  endif()
  if(EXISTS ${OUT}/${dir}/summary.json)
    message(FATAL_ERROR "replay ${ARGN} wrote a summary")
  endif()
endfunction()

if(CHECK STREQUAL "replay_wrong_kind")
  # A PCL stream replayed with a radar filter (-f), a sonar scenario's
  # sensor, radar-only options or --truth: an error naming what does not fit
  # and a non-zero exit, not an empty or half run with exit 0.
  generate_stream(pcl002 pcl)
  expect_replay_error(r1 "frames are PCL frames; filter 'ekf-ca' takes radar frames \\(filters for PCL frames: pcl-kf\\)"
                      --stream ${OUT}/pcl.kstr -f ekf-ca)
  if(EXISTS ${OUT}/r1/ekf-ca_tracks.csv OR EXISTS ${OUT}/r1/pcl_tracks.csv)
    message(FATAL_ERROR "replay of a PCL stream with ekf-ca wrote a track CSV")
  endif()
  expect_replay_error(r2 "--scenario 'uw003' is a sonar scenario; .*pcl.kstr holds PCL frames"
                      --stream ${OUT}/pcl.kstr --scenario uw003)
  expect_replay_error(r3 "--qj set the radar filters and do not apply"
                      --stream ${OUT}/pcl.kstr --qj 5 --set confirm_m=3)
  expect_replay_error(r4 "--board-gate, --robust-gate set the radar filters and do not apply"
                      --stream ${OUT}/pcl.kstr --board-gate --robust-gate 25)
  # A radar stream with the PCL tracker, and with a PCL scenario.
  execute_process(COMMAND ${SIM} generate --scenario s1 --seed 3 --out ${OUT}/s1.kstr RESULT_VARIABLE rc)
  expect_replay_error(r5 "frames are radar frames; filter 'pcl-kf' takes PCL frames" --stream ${OUT}/s1.kstr -f pcl-kf)
  expect_replay_error(r6 "--scenario pcl002: .*s1.kstr holds radar frames" --stream ${OUT}/s1.kstr -s pcl002)
elseif(CHECK STREQUAL "replay_settings")
  # replay of a PCL (sonar) stream reads --config and then --set with the
  # PCL (sonar) tracker's keys: they change the run and summary.json
  # echoes them. A key of another tracker is refused naming it, the
  # stream's kind and `list --settings`, with nothing written; a radar
  # stream keeps the radar keys.
  generate_stream(pcl002 pcl)
  generate_stream(uw003 sonar)
  execute_process(COMMAND ${SIM} generate --scenario s1 --seed 3 --out ${OUT}/s1.kstr RESULT_VARIABLE rc)
  function(replay_ok dir)
    execute_process(COMMAND ${SIM} replay ${ARGN} --no-plots --out ${OUT}/${dir}
                    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "replay ${ARGN} failed (${rc}):\n${out}${err}")
    endif()
    set(out "${out}" PARENT_SCOPE)
    file(READ ${OUT}/${dir}/summary.json summary)
    set(summary "${summary}" PARENT_SCOPE)
  endfunction()

  replay_ok(pcl_default --stream ${OUT}/pcl.kstr --truth ${OUT}/pcl.truth.csv)
  string(JSON default_m GET "${summary}" results replay pcl-kf parameters confirm_m)
  string(JSON default_rows GET "${summary}" results replay pcl-kf confirmed_track_rows)
  string(JSON default_confirm GET "${summary}" results replay pcl-kf time_to_first_confirmation_s mean)
  file(WRITE ${OUT}/pcl.json "{\"confirm_m\": 4, \"accel_sigma_mps2\": 3}")
  replay_ok(pcl_set --stream ${OUT}/pcl.kstr --truth ${OUT}/pcl.truth.csv --config ${OUT}/pcl.json --set confirm_m=2)
  if(NOT out MATCHES "parameters set by --config/--set: [^\n]*confirm_m=4 confirm_m=2\n")
    message(FATAL_ERROR "replay did not print the parameters set:\n${out}")
  endif()
  foreach(pair "parameters;confirm_m;2" "parameters;accel_sigma_mps2;3" "tracker;confirm_m;2"
               "tracker;accel_sigma_mps2;3" "parameters;confirm_n;6")
    list(GET pair 0 field)
    list(GET pair 1 key)
    list(GET pair 2 want)
    string(JSON got GET "${summary}" results replay pcl-kf ${field} ${key})
    if(NOT got EQUAL want)
      message(FATAL_ERROR "summary.json ${field}.${key} is ${got}, expected ${want}")
    endif()
  endforeach()
  # 2-of-6 confirms sooner than pcl002's 5-of-6: more confirmed-track rows.
  string(JSON rows GET "${summary}" results replay pcl-kf confirmed_track_rows)
  string(JSON confirm GET "${summary}" results replay pcl-kf time_to_first_confirmation_s mean)
  if(NOT default_m EQUAL 5 OR NOT rows GREATER default_rows OR NOT confirm LESS default_confirm)
    message(FATAL_ERROR "confirm_m=2 did not change the run: confirm_m ${default_m} -> 2, confirmed-track rows "
                        "${default_rows} -> ${rows}, first confirmation ${default_confirm} -> ${confirm} s")
  endif()

  replay_ok(sonar_default --stream ${OUT}/sonar.kstr)
  replay_ok(sonar_set --stream ${OUT}/sonar.kstr --set per_channel_gate=false)
  string(JSON gate GET "${summary}" results replay sonar-ekf parameters per_channel_gate)
  string(JSON tracker_gate GET "${summary}" results replay sonar-ekf tracker per_channel_gate)
  if(NOT gate EQUAL 0 OR (NOT tracker_gate STREQUAL "OFF" AND NOT tracker_gate STREQUAL "false"))
    message(FATAL_ERROR "summary.json per_channel_gate: parameters ${gate}, tracker ${tracker_gate}")
  endif()
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT}/sonar_default/sonar_track.csv ${OUT}/sonar_set/sonar_track.csv
                  RESULT_VARIABLE rc)
  if(rc EQUAL 0)
    message(FATAL_ERROR "per_channel_gate=false did not change sonar_track.csv")
  endif()

  # A radar stream still takes the radar keys.
  replay_ok(s1_set --stream ${OUT}/s1.kstr --set qj=50)
  string(JSON qj GET "${summary}" results replay ekf-ca parameters qj)
  if(NOT qj EQUAL 50)
    message(FATAL_ERROR "radar replay --set qj=50: summary.json parameters.qj is ${qj}")
  endif()

  file(WRITE ${OUT}/radar.json "{\"gate_d2\": 13.8}")
  set(keys "The keys of each tracker: `kestrel-sim list --settings`")
  expect_replay_error(e1 "--set qj=5: 'qj' is not a key of the PCL tracker \\([^)]*pcl.kstr holds PCL frames\\); it is a key of the radar tracker. ${keys}"
                      --stream ${OUT}/pcl.kstr --set confirm_m=3 --set qj=5)
  expect_replay_error(e2 "--config [^ ]*radar.json: gate_d2=13.8: 'gate_d2' is not a key of the PCL tracker"
                      --stream ${OUT}/pcl.kstr --config ${OUT}/radar.json)
  expect_replay_error(e3 "--set confirm_m=3: 'confirm_m' is not a key of the sonar tracker \\([^)]*sonar.kstr holds sonar frames\\); it is a key of the radar and PCL trackers. ${keys}"
                      --stream ${OUT}/sonar.kstr --set confirm_m=3)
  expect_replay_error(e4 "--set sigma_rb_m=12: 'sigma_rb_m' is not a key of the radar tracker \\([^)]*s1.kstr holds radar frames\\); it is a key of the PCL tracker"
                      --stream ${OUT}/s1.kstr --set sigma_rb_m=12)
  expect_replay_error(e5 "--set confirm_m=9: out of range \\(whole, 1..8\\)" --stream ${OUT}/pcl.kstr --set confirm_m=9)
  foreach(dir e1 e2 e3 e4 e5)
    if(EXISTS ${OUT}/${dir})
      message(FATAL_ERROR "a refused replay made its --out directory ${dir}")
    endif()
  endforeach()
elseif(CHECK STREQUAL "replay_mixed_kinds")
  # A stream holding PCL and sonar frames is refused, naming the counts.
  generate_stream(pcl002 pcl)
  generate_stream(uw003 sonar)
  execute_process(COMMAND cat ${OUT}/pcl.kstr ${OUT}/sonar.kstr OUTPUT_FILE ${OUT}/mixed.kstr RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "cat failed (${rc})")
  endif()
  expect_replay_error(r "mixed.kstr: mixes sensor kinds: 120 PCL, [0-9]+ sonar frames" --stream ${OUT}/mixed.kstr)
elseif(CHECK STREQUAL "replay_pcl_stream" OR CHECK STREQUAL "replay_sonar_stream")
  # A generated PCL (sonar) stream replayed through its own tracker: exit 0,
  # the tracks CSV of `pcl` (`sonar`) with rows that show a track was held,
  # every frame ok (or over the scan capacity, which PCL clutter reaches:
  # the frame is tracked, its excess candidates cut), and the summary naming the kind and the sensor's scenario.
  if(CHECK STREQUAL "replay_pcl_stream")
    set(scenario pcl002-hard)
    set(csv pcl_tracks.csv)
    set(filter pcl-kf)
    set(header "^time_s,track_id,associated,frame_index,rb_m,drb_mps,fd_hz,")
    set(frames 120)
  else()
    set(scenario uw003-1ms)
    set(csv sonar_track.csv)
    set(filter sonar-ekf)
    set(header "^frame,time_s,status,reported,initialised,predict_only,x_m,")
    set(frames 50)
  endif()
  generate_stream(${scenario} s)
  execute_process(COMMAND ${SIM} replay --stream ${OUT}/s.kstr --scenario ${scenario} --no-plots --out ${OUT}/replay
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "replay of a ${scenario} stream failed (${rc}):\n${out}${err}")
  endif()
  if(NOT out MATCHES "with the sensor parameters of ${scenario}\n" OR NOT out MATCHES "final status per frame: ok [0-9]+( too_many_candidates [0-9]+)?\n")
    message(FATAL_ERROR "replay did not name ${scenario} or a frame was refused:\n${out}")
  endif()
  # Every frame of the stream (120 PCL, 50 sonar) reached the tracker.
  if(NOT out MATCHES "frames ${frames}, steps ${frames};")
    message(FATAL_ERROR "replay did not step every frame:\n${out}")
  endif()
  file(STRINGS ${OUT}/replay/${csv} lines)
  list(GET lines 0 first)
  if(NOT first MATCHES "${header}")
    message(FATAL_ERROR "${csv} has another layout: ${first}")
  endif()
  if(CHECK STREQUAL "replay_pcl_stream")
    # Rows are confirmed tracks: well over half the frames hold one.
    list(LENGTH lines n)
    if(n LESS 60)
      message(FATAL_ERROR "${csv} has ${n} lines: the target was not tracked")
    endif()
    file(READ ${OUT}/replay/summary.json summary)
    string(JSON rows GET "${summary}" results replay ${filter} confirmed_track_rows)
    math(EXPR data_lines "${n} - 1")
    if(NOT rows EQUAL data_lines)
      message(FATAL_ERROR "summary.json counts ${rows} confirmed-track rows, ${csv} holds ${data_lines}")
    endif()
  else()
    # One row per frame; most must hold an estimate (reported = 1).
    set(reported 0)
    foreach(line IN LISTS lines)
      if(line MATCHES "^[0-9]+,[^,]*,ok,1,")
        math(EXPR reported "${reported} + 1")
      endif()
    endforeach()
    if(reported LESS 45)
      message(FATAL_ERROR "${csv}: ${reported} frames with an estimate: the target was not tracked")
    endif()
  endif()
  file(READ ${OUT}/replay/summary.json summary)
  string(JSON kind GET "${summary}" results replay ${filter} kind)
  string(JSON sensor GET "${summary}" results replay ${filter} sensor_scenario)
  if(NOT sensor STREQUAL scenario OR (CHECK STREQUAL "replay_pcl_stream" AND NOT kind STREQUAL "PCL")
     OR (CHECK STREQUAL "replay_sonar_stream" AND NOT kind STREQUAL "sonar"))
    message(FATAL_ERROR "summary.json says kind ${kind}, sensor ${sensor}")
  endif()
elseif(CHECK STREQUAL "replay_truth_pcl" OR CHECK STREQUAL "replay_truth_sonar")
  # A generated PCL (sonar) stream replayed with the truth generate wrote
  # beside it is scored with the kind's metrics, and they are the ones
  # `run` reports for the same scenario and seed (one run).
  if(CHECK STREQUAL "replay_truth_pcl")
    set(scenario pcl002)
    set(filter pcl-kf)
    set(files pcl)
    set(keys association_accuracy coverage_after_confirmation false_confirmed_tracks_per_run rb_rmse_m)
    set(printed "association accuracy [01]\\.[0-9]+ \\([0-9]+ of [0-9]+ frames\\), coverage after confirmation")
  else()
    set(scenario uw003)
    set(filter sonar-ekf)
    set(files sonar)
    set(keys rmse_3d_m rmse_h_m rmse_depth_m nees c_err_std_per_run_mps)
    set(printed "3D RMSE [0-9]+\\.[0-9]+ m, horizontal [0-9.]+ m, depth [0-9.]+ m")
  endif()
  generate_stream(${scenario} s)
  if(NOT EXISTS ${OUT}/s.truth.csv)
    message(FATAL_ERROR "generate --scenario ${scenario} wrote no s.truth.csv")
  endif()
  execute_process(COMMAND ${SIM} replay --stream ${OUT}/s.kstr --truth ${OUT}/s.truth.csv --no-plots --out ${OUT}/replay
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "replay --truth of a ${scenario} stream failed (${rc}):\n${out}${err}")
  endif()
  if(NOT out MATCHES "scored against [^\n]*s.truth.csv: (120|50) frames scored, 0 at a time without truth" OR
     NOT out MATCHES "${printed}")
    message(FATAL_ERROR "replay --truth did not print the ${scenario} metrics:\n${out}")
  endif()
  execute_process(COMMAND ${SIM} run --scenario ${scenario} --seed 3 --runs 1 --no-plots --out ${OUT}/run
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "run -s ${scenario} --seed 3 --runs 1 failed (${rc}):\n${out}${err}")
  endif()
  file(READ ${OUT}/replay/summary.json replay)
  file(READ ${OUT}/run/summary.json run)
  string(JSON scored GET "${replay}" results replay ${filter} scored)
  if(NOT scored STREQUAL "ON" AND NOT scored STREQUAL "true")
    message(FATAL_ERROR "summary.json says scored ${scored}")
  endif()
  foreach(key IN LISTS keys)
    string(JSON got GET "${replay}" results replay ${filter} ${key} mean)
    string(JSON want GET "${run}" results ${scenario} ${filter} ${key} mean)
    if(NOT got STREQUAL want)
      message(FATAL_ERROR "replay's ${key} is ${got}, run's of the same seed ${want}")
    endif()
  endforeach()
  # run's own run-0 truth (pcl_truth.csv, sonar_truth.csv) is the same
  # file: replay takes it too.
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT}/s.truth.csv ${OUT}/run/${files}_truth.csv
                  RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "generate's s.truth.csv differs from run's ${files}_truth.csv of the same seed")
  endif()
elseif(CHECK STREQUAL "replay_truth_mismatch")
  # Truth of another kind, or at no frame's time, is an error naming it and
  # a non-zero exit, with no summary written.
  generate_stream(pcl002 pcl)
  generate_stream(uw003 sonar)
  execute_process(COMMAND ${SIM} generate --scenario s1 --seed 3 --out ${OUT}/s1.kstr RESULT_VARIABLE rc)
  expect_replay_error(m1 "--truth [^ ]*sonar.truth.csv is a sonar truth \\(by its columns c_mps\\); [^ ]*pcl.kstr holds PCL frames"
                      --stream ${OUT}/pcl.kstr --truth ${OUT}/sonar.truth.csv)
  expect_replay_error(m2 "--truth [^ ]*s1.truth.csv is a radar truth .*pcl.kstr holds PCL frames"
                      --stream ${OUT}/pcl.kstr --truth ${OUT}/s1.truth.csv)
  expect_replay_error(m3 "--truth [^ ]*pcl.truth.csv is a PCL truth .*s1.kstr holds radar frames"
                      --stream ${OUT}/s1.kstr --truth ${OUT}/pcl.truth.csv)
  # The sonar truth moved 1000 s later: no frame time meets it.
  file(STRINGS ${OUT}/sonar.truth.csv rows)
  list(GET rows 0 header)
  list(GET rows 1 row)
  string(REGEX REPLACE "^[^,]*," "1000," row "${row}")
  file(WRITE ${OUT}/late.truth.csv "${header}\n${row}\n")
  expect_replay_error(m4 "--truth [^ ]*late.truth.csv: no frame of [^ ]*sonar.kstr is at a time of the truth .*frames 0.000000 .. 49.000000 s, truth 1000.000000 .. 1000.000000 s"
                      --stream ${OUT}/sonar.kstr --truth ${OUT}/late.truth.csv)
elseif(CHECK STREQUAL "config_set_sensor")
  # run of a PCL or sonar scenario takes its tracker's keys from --config
  # and --set (--set wins over the file) and echoes them into its summary;
  # an unknown key or a value out of range is refused by name, nothing run.
  file(WRITE ${OUT}/pcl.json "{\"accel_sigma_mps2\": 2, \"confirm_m\": 4, \"confirm_n\": 6}")
  execute_process(COMMAND ${SIM} run -s pcl002 --runs 1 --no-plots --config ${OUT}/pcl.json --set confirm_n=5
                          --out ${OUT}/pcl
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 OR NOT out MATCHES "PCL KF sa 2 m/s\\^2, nn, 4-of-5")
    message(FATAL_ERROR "run -s pcl002 --config --set failed or did not use them (${rc}):\n${out}${err}")
  endif()
  file(READ ${OUT}/pcl/summary.json summary)
  foreach(pair "accel_sigma_mps2=2" "confirm_m=4" "confirm_n=5" "gate_confirmed=0.99")
    string(REPLACE "=" ";" kv ${pair})
    list(GET kv 0 key)
    list(GET kv 1 want)
    string(JSON got GET ${summary} results pcl002 pcl-kf parameters ${key})
    if(NOT got EQUAL want)
      message(FATAL_ERROR "summary.json results.pcl002.pcl-kf.parameters.${key} is ${got}, expected ${want}")
    endif()
  endforeach()
  execute_process(COMMAND ${SIM} run -s uw003 --runs 1 --no-plots --set per_channel_gate=false --set gate_k_sigma=3
                          --out ${OUT}/sonar
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 OR NOT out MATCHES "sonar EKF, no gate,")
    message(FATAL_ERROR "run -s uw003 --set failed or did not use it (${rc}):\n${out}${err}")
  endif()
  file(READ ${OUT}/sonar/summary.json summary)
  string(JSON gate GET ${summary} results uw003 sonar-ekf parameters per_channel_gate)
  string(JSON k GET ${summary} results uw003 sonar-ekf tracker gate_k_sigma)
  if(NOT gate EQUAL 0 OR NOT k EQUAL 3)
    message(FATAL_ERROR "summary.json results.uw003.sonar-ekf: per_channel_gate ${gate}, gate_k_sigma ${k}")
  endif()
  foreach(bad "pcl002;confirm_m=9;--set confirm_m=9: out of range \\(whole, 1..8\\)"
              "uw003;qj=5;--set qj=5: unknown key of the sonar tracker")
    list(GET bad 0 scenario)
    list(GET bad 1 set)
    list(GET bad 2 pattern)
    execute_process(COMMAND ${SIM} run -s ${scenario} --runs 1 --no-plots --set ${set} --out ${OUT}/bad
                    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(rc EQUAL 0 OR NOT err MATCHES "${pattern}")
      message(FATAL_ERROR "run -s ${scenario} --set ${set} was not refused by name (${rc}):\n${out}${err}")
    endif()
    if(EXISTS ${OUT}/bad)
      message(FATAL_ERROR "run -s ${scenario} --set ${set} wrote files")
    endif()
  endforeach()
elseif(CHECK STREQUAL "one_summary")
  # run of every sensor kind and of a multi-target scenario writes one
  # summary.json schema, results[<scenario>][<filter>] with the frames'
  # kind; runs into one directory add their entries to the same file.
  foreach(args "-s;s1;-f;imm" "-s;pcl002" "-s;uw003" "-s;crossing")
    execute_process(COMMAND ${SIM} run ${args} --runs 2 --no-plots --out ${OUT}/all
                    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "run ${args} failed (${rc}):\n${out}${err}")
    endif()
  endforeach()
  file(READ ${OUT}/all/summary.json summary)
  string(JSON schema GET "${summary}" schema)
  if(NOT schema STREQUAL "kestrel-sim-summary/1")
    message(FATAL_ERROR "summary.json schema ${schema}")
  endif()
  foreach(entry "s1;imm;radar;rmse_m" "pcl002;pcl-kf;PCL;association_accuracy" "uw003;sonar-ekf;sonar;rmse_3d_m"
                "crossing;ekf-ca;radar;gospa_m")
    list(POP_FRONT entry scenario filter want_kind)
    string(JSON kind GET "${summary}" results ${scenario} ${filter} kind)
    string(JSON runs GET "${summary}" results ${scenario} ${filter} runs)
    string(JSON mean GET "${summary}" results ${scenario} ${filter} ${entry} mean)
    if(NOT kind STREQUAL want_kind OR NOT runs EQUAL 2 OR NOT mean MATCHES "^[0-9]")
      message(FATAL_ERROR "results.${scenario}.${filter}: kind '${kind}', runs ${runs}, ${entry} mean '${mean}'")
    endif()
  endforeach()
  string(JSON targets GET "${summary}" results crossing ekf-ca targets)
  string(JSON associator GET "${summary}" results crossing ekf-ca associator)
  if(NOT targets EQUAL 2 OR NOT associator STREQUAL "gnn")
    message(FATAL_ERROR "results.crossing.ekf-ca: targets ${targets}, associator ${associator}")
  endif()
elseif(CHECK STREQUAL "sweep_kinds")
  # sweep takes a PCL, sonar or multi-target scenario too: one run per
  # value, each value's summary entry with its swept value in one file; a
  # radar-only option or a value out of range is refused with nothing run.
  foreach(args "pcl002;pcl-kf;accel_sigma_mps2;2;4;-s;pcl002;--set;accel_sigma_mps2=2,4"
               "crossing;imm;imm.p_stay;0.8;0.95;-s;crossing;-f;imm;--set;imm.p_stay=0.8,0.95")
    list(POP_FRONT args scenario filter key v1 v2)
    execute_process(COMMAND ${SIM} sweep ${args} --runs 1 --out ${OUT}/${scenario}
                    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "sweep ${args} failed (${rc}):\n${out}${err}")
    endif()
    file(READ ${OUT}/${scenario}/summary.json summary)
    foreach(v ${v1} ${v2})
      string(JSON value GET "${summary}" results ${scenario} ${filter}-${key}${v} sweep value)
      string(JSON runs GET "${summary}" results ${scenario} ${filter}-${key}${v} runs)
      if(NOT value EQUAL v OR NOT runs EQUAL 1)
        message(FATAL_ERROR "sweep ${args}: entry ${filter}-${key}${v} has value ${value}, runs ${runs}")
      endif()
    endforeach()
  endforeach()
  string(JSON a GET "${summary}" results crossing imm-imm.p_stay0.8 gospa_m mean)
  string(JSON b GET "${summary}" results crossing imm-imm.p_stay0.95 gospa_m mean)
  if(a STREQUAL b)
    message(FATAL_ERROR "sweep of imm.p_stay: the same GOSPA ${a} for both values")
  endif()
  foreach(bad "--qj set the radar filters and do not apply;--set;gate_k_sigma=2,3;--qj;5"
              "--set gate_k_sigma=-3: out of range;--set;gate_k_sigma=2,-3")
    list(POP_FRONT bad pattern)
    execute_process(COMMAND ${SIM} sweep -s uw003 ${bad} --runs 1 --out ${OUT}/bad
                    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(rc EQUAL 0 OR NOT err MATCHES "${pattern}" OR EXISTS ${OUT}/bad)
      message(FATAL_ERROR "sweep -s uw003 ${bad} was not refused before running (${rc}):\n${out}${err}")
    endif()
  endforeach()
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
            pcl002/summary.json uw003/summary.json)
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
elseif(CHECK STREQUAL "run_kind_options")
  # run takes pcl's and multi's own options for the scenarios they fit, and
  # they reach the run and its summary; for another kind each is refused by
  # name, with nothing run.
  execute_process(COMMAND ${SIM} run -s pcl002 --runs 2 --associator gnn --manager score --gate-tentative 0.99
                          --no-plots --out ${OUT}/pcl
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 OR NOT out MATCHES "pcl002: 2 runs [^\n]*, gnn, track score,")
    message(FATAL_ERROR "run -s pcl002 --associator gnn --manager score (${rc}):\n${out}${err}")
  endif()
  file(READ ${OUT}/pcl/summary.json summary)
  foreach(entry "associator;gnn" "manager;score" "gate_tentative;0.99")
    list(POP_FRONT entry key want)
    string(JSON got GET "${summary}" results pcl002 pcl-kf tracker ${key})
    if(NOT got STREQUAL want)
      message(FATAL_ERROR "pcl002 summary tracker.${key} is '${got}', expected '${want}'")
    endif()
  endforeach()
  execute_process(COMMAND ${SIM} run -s crossing --runs 2 --associator nn --gate-tentative 0.99 --compare-oracle
                          --cutoff 300 --order 1 --persistence 2 --no-plots --out ${OUT}/crossing
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 OR NOT out MATCHES "crossing: 2 targets, 2 runs [^\n]*, nn, c 300 m, p 1\n.* oracle, mean over runs")
    message(FATAL_ERROR "run -s crossing --associator nn --compare-oracle (${rc}):\n${out}${err}")
  endif()
  file(READ ${OUT}/crossing/summary.json summary)
  foreach(entry "associator;nn" "cutoff_m;300" "order;1" "persistence_steps;2" "parameters;gate_tentative;0.99")
    list(POP_BACK entry want)
    string(JSON got GET "${summary}" results crossing ekf-ca ${entry})
    if(NOT got EQUAL want AND NOT got STREQUAL want)
      message(FATAL_ERROR "crossing summary ${entry} is '${got}', expected '${want}'")
    endif()
  endforeach()
  string(JSON oracle_gospa GET "${summary}" results crossing ekf-ca oracle gospa_m mean)
  if(NOT oracle_gospa MATCHES "^[0-9]")
    message(FATAL_ERROR "crossing summary has no oracle GOSPA ('${oracle_gospa}')")
  endif()
  foreach(args "s1;single-target radar;--associator;gnn;--associator does not apply to it"
               "uw003;sonar;--manager;score;--gate-tentative;0.99;--manager, --gate-tentative do not apply to it"
               "crossing;multi-target radar;--manager;score;--manager does not apply to it \\(it takes --associator, --gate-tentative"
               "pcl002;PCL;--compare-oracle;--compare-oracle does not apply to it \\(it takes --associator, --manager")
    list(POP_FRONT args scenario kind)
    list(POP_BACK args want)
    execute_process(COMMAND ${SIM} run -s ${scenario} --runs 1 ${args} --no-plots --out ${OUT}/refused-${scenario}
                    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(rc EQUAL 0 OR NOT err MATCHES "scenario '${scenario}' is a ${kind} scenario; ${want}")
      message(FATAL_ERROR "run -s ${scenario} ${args} was not refused by name (${rc}):\n${out}${err}")
    endif()
    if(EXISTS ${OUT}/refused-${scenario}/summary.json)
      message(FATAL_ERROR "run -s ${scenario} ${args} wrote a summary")
    endif()
  endforeach()
elseif(CHECK STREQUAL "replay_multi_target")
  # generate writes every target of a multi-target scenario into its truth
  # (target column); replay scores the stream against it with the tracker
  # and metrics of run: the same figures as run of that seed. Options of the
  # single-target scoring are refused by name, with nothing written.
  execute_process(COMMAND ${SIM} generate -s crossing --seed 3 --out ${OUT}/crossing.stream
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  file(STRINGS ${OUT}/crossing.truth.csv truth_lines)
  list(GET truth_lines 0 header)
  list(LENGTH truth_lines rows)
  if(NOT rc EQUAL 0 OR NOT header STREQUAL "time_s,target,x_m,y_m,vx_mps,vy_mps" OR NOT rows EQUAL 123)
    message(FATAL_ERROR "generate -s crossing: truth header '${header}', ${rows} lines (${rc}):\n${out}${err}")
  endif()
  execute_process(COMMAND ${SIM} replay --stream ${OUT}/crossing.stream --truth ${OUT}/crossing.truth.csv --no-plots
                          --out ${OUT}/replay
                  RESULT_VARIABLE rc OUTPUT_VARIABLE replayed ERROR_VARIABLE err)
  execute_process(COMMAND ${SIM} run -s crossing --seed 3 --runs 1 --no-plots --out ${OUT}/run
                  RESULT_VARIABLE rc_run OUTPUT_VARIABLE ran ERROR_VARIABLE err_run)
  if(NOT rc EQUAL 0 OR NOT rc_run EQUAL 0 OR NOT replayed MATCHES "2 targets in [^\n]*; scored 61 frames")
    message(FATAL_ERROR "replay (${rc}):\n${replayed}${err}\nrun (${rc_run}):\n${ran}${err_run}")
  endif()
  string(REGEX MATCH "GOSPA \\(mean over steps\\)[^\n]*\n(.*\n)*  targets never confirmed[^\n]*" figures_replay "${replayed}")
  string(REGEX MATCH "GOSPA \\(mean over steps\\)[^\n]*\n(.*\n)*  targets never confirmed[^\n]*" figures_run "${ran}")
  if(figures_replay STREQUAL "" OR NOT figures_replay STREQUAL figures_run)
    message(FATAL_ERROR "replay's figures differ from run's:\n${figures_replay}\n--- run:\n${figures_run}")
  endif()
  file(READ ${OUT}/replay/summary.json summary)
  string(JSON targets GET "${summary}" results replay ekf-ca targets)
  string(JSON matched GET "${summary}" results replay ekf-ca truth_frames matched)
  string(JSON gospa GET "${summary}" results replay ekf-ca gospa_m mean)
  if(NOT targets EQUAL 2 OR NOT matched EQUAL 61 OR NOT gospa MATCHES "^[0-9]")
    message(FATAL_ERROR "replay summary: targets ${targets}, matched ${matched}, GOSPA '${gospa}'")
  endif()
  # The replay's multi_steps.csv carries each scored frame's own time: the
  # plot CSV without its frames at 10-19 s leaves step 10 at 20 s (k times
  # the mean spacing would say 12 s).
  file(STRINGS ${OUT}/crossing.plots.csv plot_lines)
  list(FILTER plot_lines EXCLUDE REGEX "^1[0-9]\\.")
  list(JOIN plot_lines "\n" gapped)
  file(WRITE ${OUT}/gapped.plots.csv "${gapped}\n")
  execute_process(COMMAND ${SIM} replay --csv ${OUT}/gapped.plots.csv --truth ${OUT}/crossing.truth.csv --no-plots
                          --out ${OUT}/gapped
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  file(STRINGS ${OUT}/gapped/multi_steps.csv step_lines)
  list(LENGTH step_lines n_steps)
  if(NOT rc EQUAL 0 OR NOT n_steps EQUAL 52)
    message(FATAL_ERROR "replay of the gapped plot CSV: ${n_steps} lines in multi_steps.csv (${rc}):\n${out}${err}")
  endif()
  list(GET step_lines 10 step9)
  list(GET step_lines 11 step10)
  if(NOT step9 MATCHES "^9,9," OR NOT step10 MATCHES "^10,20,")
    message(FATAL_ERROR "multi_steps.csv of the gapped replay: '${step9}', '${step10}' (want steps 9 at 9 s, 10 at 20 s)")
  endif()
  execute_process(COMMAND ${SIM} replay --stream ${OUT}/crossing.stream --truth ${OUT}/crossing.truth.csv --ungated
                          --no-plots --out ${OUT}/refused
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(rc EQUAL 0 OR NOT err MATCHES "holds 2 targets, scored by the multi-target tracker; --ungated does not apply"
     OR EXISTS ${OUT}/refused/summary.json)
    message(FATAL_ERROR "replay --ungated of a multi-target truth was not refused by name (${rc}):\n${out}${err}")
  endif()
  # --associator gnn without a truth runs the same multi-target tracker:
  # the same track CSV as the scored replay, a summary entry marked not
  # scored; --associator nn another one. A PCL stream refuses the option.
  execute_process(COMMAND ${SIM} replay --stream ${OUT}/crossing.stream --associator gnn --no-plots --out ${OUT}/gnn
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  file(READ ${OUT}/replay/ekf-ca_tracks.csv scored_tracks)
  file(READ ${OUT}/gnn/ekf-ca_tracks.csv gnn_tracks)
  if(NOT rc EQUAL 0 OR NOT out MATCHES "multi-target tracker, ekf-ca, gnn; 61 frames stepped, [0-9]+ confirmed-track rows"
     OR NOT out MATCHES "not scored \\(no --truth\\)" OR NOT gnn_tracks STREQUAL scored_tracks)
    message(FATAL_ERROR "replay --associator gnn without a truth (${rc}):\n${out}${err}")
  endif()
  file(READ ${OUT}/gnn/summary.json summary)
  string(JSON scored GET "${summary}" results replay ekf-ca scored)
  string(JSON associator GET "${summary}" results replay ekf-ca associator)
  if(NOT scored STREQUAL "OFF" OR NOT associator STREQUAL "gnn")
    message(FATAL_ERROR "replay --associator gnn summary: scored '${scored}', associator '${associator}'")
  endif()
  execute_process(COMMAND ${SIM} replay --stream ${OUT}/crossing.stream --truth ${OUT}/crossing.truth.csv
                          --associator nn --no-plots --out ${OUT}/nn
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 OR NOT out MATCHES "2 targets in [^\n]*; scored 61 frames [^\n]*, ekf-ca, nn, c 500 m")
    message(FATAL_ERROR "replay --associator nn with the truth (${rc}):\n${out}${err}")
  endif()
  generate_stream(pcl002 pcl)
  expect_replay_error(pcl_gnn "--associator gnn: [^\n]*pcl.kstr holds PCL frames" --stream ${OUT}/pcl.kstr
                      --associator gnn)
else()
  message(FATAL_ERROR "unknown CHECK '${CHECK}'")
endif()
