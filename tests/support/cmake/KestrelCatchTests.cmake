# SPDX-License-Identifier: Apache-2.0
# kestrel_catch_tests(<target> [TEST_PREFIX <prefix>])
#
# Registers every Catch2 test case of <target> as its own CTest test, like
# Catch's catch_discover_tests, with three differences that keep a case from
# being lost:
#  - names are read line by line and never pass through a CMake list, so a
#    ';' or an unbalanced '[' or ']' in a name cannot split or merge entries;
#  - a name the Catch2 command line cannot select exactly (a leading or
#    trailing '*', a ';', a '"') is not registered with a filter that would
#    match nothing: it becomes a failing test that names it;
#  - every test runs with `--warn NoTests`, so a filter that matches nothing
#    exits non-zero instead of passing.
# Each run also logs the names of the cases it executed (see
# tests/support/case_log.cpp); tools/ci/check_cases_ran.py compares that log
# with the binary's own listing after a full ctest run.
set(_kestrel_catch_add_tests_script ${CMAKE_CURRENT_LIST_DIR}/KestrelCatchAddTests.cmake)

function(kestrel_catch_tests target)
  cmake_parse_arguments(arg "" "TEST_PREFIX" "" ${ARGN})
  set(ctest_file "${CMAKE_CURRENT_BINARY_DIR}/${target}_tests.cmake")
  set(list_file "${KESTREL_CASE_LIST_DIR}/${target}.list")
  add_custom_command(TARGET ${target} POST_BUILD
    BYPRODUCTS "${ctest_file}"
    COMMAND "${CMAKE_COMMAND}"
            -D "TEST_TARGET=${target}"
            -D "TEST_EXECUTABLE=$<TARGET_FILE:${target}>"
            -D "TEST_WORKING_DIR=${CMAKE_CURRENT_BINARY_DIR}"
            -D "TEST_PREFIX=${arg_TEST_PREFIX}"
            -D "CASE_LOG_DIR=${KESTREL_CASE_LOG_DIR}"
            -D "CASE_LIST_FILE=${list_file}"
            -D "CTEST_FILE=${ctest_file}"
            -P "${_kestrel_catch_add_tests_script}"
    VERBATIM)
  # The case list exists once the binary is built. Until then CTest sees one
  # failing <target>_NOT_BUILT test instead of an error that stops every
  # other test, so `ctest -L <label>` runs tests that need no build.
  set(include_file "${CMAKE_CURRENT_BINARY_DIR}/${target}_include.cmake")
  file(WRITE "${include_file}"
    "if(EXISTS \"${ctest_file}\")\n"
    "  include(\"${ctest_file}\")\n"
    "else()\n"
    "  add_test(${target}_NOT_BUILT ${target}_NOT_BUILT)\n"
    "endif()\n")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES "${include_file}")
endfunction()
