# SPDX-License-Identifier: Apache-2.0
# Run after each build of a Catch2 test binary (KestrelCatchTests.cmake):
# lists its cases and writes the CTest script that registers one test per
# case. Names are handled as strings, never as CMake lists.
execute_process(
  COMMAND "${TEST_EXECUTABLE}" --list-test-names-only
  OUTPUT_VARIABLE listing
  RESULT_VARIABLE listed
  WORKING_DIRECTORY "${TEST_WORKING_DIR}")
# Catch2 v2 exits with the number of cases listed, capped at 255 (so 0
# means none, and anything else but a count is a crash).
if(NOT listed MATCHES "^[0-9]+$" OR listed EQUAL 0)
  message(FATAL_ERROR "${TEST_EXECUTABLE} --list-test-names-only failed or listed no case (${listed})")
endif()

# A bracket argument whose delimiter cannot occur in the text.
function(bracket out text)
  set(eq "=")
  while(text MATCHES "\\]${eq}\\]")
    string(APPEND eq "=")
  endwhile()
  set(${out} "[${eq}[${text}]${eq}]" PARENT_SCOPE)
endfunction()

set(script "")
set(names "")
set(count 0)
set(rest "${listing}")
while(NOT rest STREQUAL "")
  string(FIND "${rest}" "\n" nl)
  if(nl EQUAL -1)
    set(name "${rest}")
    set(rest "")
  else()
    string(SUBSTRING "${rest}" 0 ${nl} name)
    math(EXPR from "${nl} + 1")
    string(SUBSTRING "${rest}" ${from} -1 rest)
  endif()
  string(REGEX REPLACE "\r$" "" name "${name}")
  if(name STREQUAL "")
    continue()
  endif()
  math(EXPR count "${count} + 1")
  string(APPEND names "${name}\n")
  bracket(test_name "${TEST_PREFIX}${name}")
  if(name MATCHES "^[*~ ]|[* ]$|[;\"]")
    # Catch2 would read these characters as a wildcard, an exclusion or a
    # quote (or CTest as a list separator): fail loudly instead.
    bracket(msg "Catch2 case name cannot be selected exactly; rename it: ${name}")
    string(APPEND script "add_test(${test_name} \"${CMAKE_COMMAND}\" -E echo ${msg})\n")
    string(APPEND script "set_tests_properties(${test_name} PROPERTIES WILL_FAIL TRUE LABELS discovery)\n")
    continue()
  endif()
  # Catch2 test-spec escapes: backslash, comma and brackets.
  set(filter "${name}")
  string(REPLACE "\\" "\\\\" filter "${filter}")
  foreach(c "," "[" "]")
    string(REPLACE "${c}" "\\${c}" filter "${filter}")
  endforeach()
  bracket(filter_arg "${filter}")
  bracket(exe "${TEST_EXECUTABLE}")
  bracket(wd "${TEST_WORKING_DIR}")
  bracket(env "KESTREL_CASE_LOG=${CASE_LOG_DIR}/${TEST_TARGET}.log")
  string(APPEND script "add_test(${test_name} ${exe} ${filter_arg} --warn NoTests)\n")
  string(APPEND script "set_tests_properties(${test_name} PROPERTIES WORKING_DIRECTORY ${wd} ENVIRONMENT ${env})\n")
endwhile()
if(listed LESS 255 AND NOT count EQUAL listed)
  message(FATAL_ERROR "${TEST_EXECUTABLE}: read ${count} names, Catch2 reported ${listed}")
endif()
file(WRITE "${CTEST_FILE}" "${script}")
file(WRITE "${CASE_LIST_FILE}" "${names}")
