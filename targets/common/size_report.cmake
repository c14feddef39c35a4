# SPDX-License-Identifier: Apache-2.0
# Post-link size report and size budget of an image:
#   cmake -DSIZE=<binutils size> -DELF=<image> -DOUT=<size.txt>
#         [-DJSON=<size.json>] [-DLABEL=<row name>] [-DBOARD=<board>] [-DBUILD_TYPE=<type>]
#         [-DTEXT_BUDGET=<bytes>] [-DDATA_BUDGET=<bytes>] [-DBSS_BUDGET=<bytes>]
#         -P size_report.cmake
# Writes the Berkeley totals (text = code and read-only data, in flash on a
# microcontroller; data = initialised variables, whose initial values also
# sit in flash; bss = zeroed RAM, plus NOLOAD sections such as .noinit and
# .stack on the Cortex-M images) and the per-section table to OUT, the same
# figures as JSON to JSON (read by targets/common/footprint_table.py), and
# prints the totals.
#
# Budgets: a total over its budget fails the build and renames the image to
# <image>.rejected, so the failure repeats on the next build and nobody
# flashes an image that broke its budget. Budgets are set per board in the
# board's CMakeLists.txt (kestrel_board_evidence) from the measured figures
# plus headroom; docs/footprint.md says how.
cmake_minimum_required(VERSION 3.25)

foreach(var SIZE ELF OUT)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "size_report.cmake: -D${var}=... is required")
  endif()
endforeach()

execute_process(COMMAND ${SIZE} -B ${ELF} RESULT_VARIABLE rc_b OUTPUT_VARIABLE berkeley ERROR_VARIABLE err)
execute_process(COMMAND ${SIZE} -A -x ${ELF} RESULT_VARIABLE rc_a OUTPUT_VARIABLE sysv ERROR_VARIABLE err2)
if(NOT rc_b EQUAL 0 OR NOT rc_a EQUAL 0)
  message(FATAL_ERROR "size_report.cmake: ${SIZE} failed on ${ELF}: ${err}${err2}")
endif()

# Berkeley totals: the second line is "text data bss dec hex filename".
string(REPLACE "\n" ";" berkeley_lines "${berkeley}")
list(GET berkeley_lines 1 totals)
string(REGEX MATCH "^[ \t]*([0-9]+)[ \t]+([0-9]+)[ \t]+([0-9]+)" m "${totals}")
if(NOT m)
  message(FATAL_ERROR "size_report.cmake: cannot read the Berkeley totals of ${ELF}:\n${berkeley}")
endif()
set(text ${CMAKE_MATCH_1})
set(data ${CMAKE_MATCH_2})
set(bss ${CMAKE_MATCH_3})

# Every allocated section with its size, from the SysV table (hex with -x);
# debug, comment and attribute sections are not part of the image.
set(summary "")
set(sections_json "")
string(REPLACE "\n" ";" sysv_lines "${sysv}")
foreach(line IN LISTS sysv_lines)
  if(line MATCHES "^(\\.[^ \t]+)[ \t]+0x([0-9a-fA-F]+)[ \t]+0x[0-9a-fA-F]+")
    set(name "${CMAKE_MATCH_1}")
    math(EXPR bytes "0x${CMAKE_MATCH_2}" OUTPUT_FORMAT DECIMAL)
    if(bytes EQUAL 0 OR name MATCHES "^\\.(debug|comment|ARM\\.attributes|riscv\\.attributes|gnu\\.attributes|symtab|strtab|shstrtab|stab|note\\.gnu\\.build-id)")
      continue()
    endif()
    string(APPEND summary "${name}=${bytes} ")
    if(sections_json)
      string(APPEND sections_json ", ")
    endif()
    string(APPEND sections_json "\"${name}\": ${bytes}")
  endif()
endforeach()

if(NOT DEFINED LABEL)
  get_filename_component(LABEL ${ELF} NAME)
endif()
foreach(var BOARD BUILD_TYPE)
  if(NOT DEFINED ${var})
    set(${var} "")
  endif()
endforeach()

# Budget check.
set(over "")
set(budget_json "")
foreach(part text data bss)
  string(TOUPPER ${part} up)
  if(DEFINED ${up}_BUDGET AND NOT "${${up}_BUDGET}" STREQUAL "")
    if(budget_json)
      string(APPEND budget_json ", ")
    endif()
    string(APPEND budget_json "\"${part}\": ${${up}_BUDGET}")
    if(${${part}} GREATER ${${up}_BUDGET})
      math(EXPR excess "${${part}} - ${${up}_BUDGET}")
      string(APPEND over "  ${part} = ${${part}} bytes, budget ${${up}_BUDGET} (+${excess})\n")
    endif()
  endif()
endforeach()

file(WRITE ${OUT} "# ${ELF}\n# Berkeley totals (${SIZE} -B):\n${berkeley}\n"
                  "# Sections, bytes: ${summary}\n"
                  "# Budgets: text ${TEXT_BUDGET} data ${DATA_BUDGET} bss ${BSS_BUDGET}\n\n"
                  "# Per section (${SIZE} -A -x):\n${sysv}")
if(DEFINED JSON)
  get_filename_component(elf_name ${ELF} NAME)
  file(WRITE ${JSON} "{\n  \"label\": \"${LABEL}\",\n  \"board\": \"${BOARD}\",\n  \"build_type\": \"${BUILD_TYPE}\",\n"
                     "  \"elf\": \"${elf_name}\",\n  \"text\": ${text},\n  \"data\": ${data},\n  \"bss\": ${bss},\n"
                     "  \"budget\": {${budget_json}},\n  \"sections\": {${sections_json}}\n}\n")
endif()
message(STATUS "Image size (bytes): text ${text}, data ${data}, bss ${bss} "
               "(budgets ${TEXT_BUDGET}/${DATA_BUDGET}/${BSS_BUDGET})\n-- Sections: ${summary}\n-- Written to ${OUT}")

if(over)
  file(RENAME ${ELF} ${ELF}.rejected)
  message(FATAL_ERROR "size_report.cmake: ${ELF} is over its size budget:\n${over}"
                      "The image was renamed to ${ELF}.rejected. Either make it smaller or, if the "
                      "growth is deliberate, raise the budget in the board's CMakeLists.txt "
                      "(kestrel_board_evidence) and say why in the commit (docs/footprint.md, \"Budgets\").")
endif()
