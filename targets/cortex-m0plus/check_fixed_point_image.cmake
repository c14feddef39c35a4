# SPDX-License-Identifier: Apache-2.0
# Post-link check of the fixed-point image (docs/fixed-point.md): cmake -DNM=<nm>
#   -DELF=<image> -P check_fixed_point_image.cmake
# The Q31.32 tracker is integer arithmetic only, so the image must hold no
# double-precision soft-float routine (__aeabi_d*, __adddf3, conversions to
# or from double, ...) and nothing from libm (sin, atan2, sqrt, ...). Either
# one means a double or a <cmath> call reached the board's code path: the
# check fails and renames the image to <image>.rejected (as check_symbols.cmake
# does), naming the symbols; the map file's cross-reference table (--cref)
# names who pulled them in. Single-precision soft-float helpers are listed
# without failing (none are expected either).
cmake_minimum_required(VERSION 3.25)
foreach(var NM ELF)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "check_fixed_point_image.cmake: -D${var}=... is required")
  endif()
endforeach()

execute_process(COMMAND ${NM} ${ELF} RESULT_VARIABLE rc OUTPUT_VARIABLE all ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "check_fixed_point_image.cmake: ${NM} failed on ${ELF}: ${err}")
endif()
string(REPLACE "\n" ";" lines "${all}")
set(double_or_libm "")
set(single "")
foreach(line IN LISTS lines)
  if(NOT line MATCHES "^[0-9a-fA-F ]* [A-Za-z?] ([^ ]+)$")
    continue()
  endif()
  set(name "${CMAKE_MATCH_1}")
  if(name MATCHES "^__aeabi_(d[a-z]+|[iu]?[il]2d|f2d|l2d|ul2d|d2[a-z]+)$"
     OR name MATCHES "^__(add|sub|mul|div|neg|eq|ne|lt|le|gt|ge|unord|cmp)df[23]$"
     OR name MATCHES "^__(extendsfdf2|truncdfsf2|fix(uns)?df[sd]i|float(un)?[sd]idf)$"
     OR name MATCHES "^__ieee754_" OR name MATCHES "^__kernel_"
     OR name MATCHES "^(sin|cos|tan|asin|acos|atan|atan2|hypot|sqrt|cbrt|exp|exp2|expm1|log|log2|log10|log1p|pow|fmod|remainder|remquo|floor|ceil|trunc|round|lround|llround|nearbyint|rint|lrint|scalbn|ldexp|frexp|modf|copysign|fabs|fmin|fmax|fma|finite|isnan|isinf|__fpclassify[fd]?)[fl]?$")
    list(APPEND double_or_libm "${name}")
  elseif(name MATCHES "^__aeabi_f" OR name MATCHES "^__(add|sub|mul|div|neg|eq|ne|lt|le|gt|ge|unord|cmp)sf[23]$"
         OR name MATCHES "^__(fix(uns)?sf[sd]i|float(un)?[sd]isf)$")
    list(APPEND single "${name}")
  endif()
endforeach()

if(single)
  list(REMOVE_DUPLICATES single)
  list(JOIN single " " single_text)
  message(STATUS "check_fixed_point_image.cmake: single-precision soft-float helpers in ${ELF}: ${single_text}")
endif()
if(double_or_libm)
  list(REMOVE_DUPLICATES double_or_libm)
  list(JOIN double_or_libm "\n  " text)
  file(RENAME ${ELF} ${ELF}.rejected)
  message(FATAL_ERROR "check_fixed_point_image.cmake: ${ELF} holds double soft-float or libm symbols:\n  ${text}\n"
                      "The image was renamed to ${ELF}.rejected.")
endif()
message(STATUS "check_fixed_point_image.cmake: no double soft-float and no libm symbol in ${ELF}")
