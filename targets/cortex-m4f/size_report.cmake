# Post-link size report of an image: cmake -DSIZE=<arm-none-eabi-size>
#   -DELF=<image> -DOUT=<size.txt> -P size_report.cmake
# Writes the Berkeley totals (text = flash code and constants, data = .data
# initial values in flash and the variables in RAM, bss = zeroed RAM plus the
# NOLOAD .noinit and .stack) and the per-section table to OUT, and prints
# the totals.
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

# Sizes of a few sections by name from the SysV table (hex with -x).
set(summary "")
foreach(section .isr_vector .text .rodata .data .bss .noinit .stack)
  string(REGEX MATCH "\n\\${section}[ \t]+0x([0-9a-fA-F]+)" m "${sysv}")
  if(m)
    math(EXPR bytes "0x${CMAKE_MATCH_1}" OUTPUT_FORMAT DECIMAL)
  else()
    set(bytes 0)
  endif()
  string(APPEND summary "${section}=${bytes} ")
endforeach()

file(WRITE ${OUT} "# ${ELF}\n# Berkeley totals (arm-none-eabi-size -B):\n${berkeley}\n"
                  "# Sections, bytes: ${summary}\n\n# Per section (arm-none-eabi-size -A -x):\n${sysv}")
string(STRIP "${berkeley}" berkeley)
message(STATUS "Image size (bytes):\n${berkeley}\n-- Sections: ${summary}\n-- Written to ${OUT}")
