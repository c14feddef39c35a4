# SPDX-License-Identifier: Apache-2.0
# Post-link check of the float image: cmake -DNM=<nm> -DELF=<image>
#   -P check_float_image.cmake
# The Cortex-M4F's FPU is single precision, so a double operation is a
# libgcc soft-float routine (__aeabi_d*, conversions to or from double): the
# image must hold none, nor newlib's large-argument sinf/cosf reduction
# (__kernel_rem_pio2f and its 2/pi table; trig_reduction.cpp replaces the
# reduction). Either one fails the check, renames the image to
# <image>.rejected and names the symbols; the map file's cross-reference
# table (--cref) names who pulled them in.
cmake_minimum_required(VERSION 3.25)
foreach(var NM ELF)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "check_float_image.cmake: -D${var}=... is required")
  endif()
endforeach()

execute_process(COMMAND ${NM} ${ELF} RESULT_VARIABLE rc OUTPUT_VARIABLE all ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "check_float_image.cmake: ${NM} failed on ${ELF}: ${err}")
endif()
string(REPLACE "\n" ";" lines "${all}")
set(bad "")
foreach(line IN LISTS lines)
  if(NOT line MATCHES "^[0-9a-fA-F ]* [A-Za-z?] ([^ ]+)$")
    continue()
  endif()
  set(name "${CMAKE_MATCH_1}")
  if(name MATCHES "^__aeabi_(d[a-z]+[0-9]*|[iu]?[il]2d|f2d|l2d|ul2d|d2[a-z]+)$"
     OR name MATCHES "^__(add|sub|mul|div|neg|eq|ne|lt|le|gt|ge|unord|cmp)df[23]$"
     OR name MATCHES "^__(extendsfdf2|truncdfsf2|fix(uns)?df[sd]i|float(un)?[sd]idf)$"
     OR name MATCHES "^(__kernel_rem_pio2f|two_over_pi|npio2_hw)$")
    list(APPEND bad "${name}")
  endif()
endforeach()
if(bad)
  list(REMOVE_DUPLICATES bad)
  list(JOIN bad "\n  " text)
  file(RENAME ${ELF} ${ELF}.rejected)
  message(FATAL_ERROR "check_float_image.cmake: ${ELF} holds double soft-float or large-argument reduction symbols:\n"
                      "  ${text}\nThe image was renamed to ${ELF}.rejected.")
endif()
message(STATUS "check_float_image.cmake: no double soft-float and no large-argument sinf/cosf reduction in ${ELF}")
