# SPDX-License-Identifier: Apache-2.0
# How an RP2040 (Cortex-M0+) image is compiled and linked: the Cortex-M4F
# model (targets/cortex-m4f/image.cmake, flags explained in docs/porting.md)
# with the M0+ linker script. Included by targets/cortex-m0plus/CMakeLists.txt
# and by the heap-guard probe project of tests/targets.
#
#   kestrel_m0plus_codegen   INTERFACE library: code generation flags.
#   kestrel_m0plus_image(<executable>)
#                            linker script, start-up model, --gc-sections, map
#                            file, memory-usage print, and the heap guard.
include_guard(GLOBAL)

set(KESTREL_M0PLUS_DIR ${CMAKE_CURRENT_LIST_DIR})
include(${CMAKE_CURRENT_LIST_DIR}/../common/evidence.cmake)

if(NOT TARGET kestrel_m0plus_codegen)
  add_library(kestrel_m0plus_codegen INTERFACE)
  target_compile_options(kestrel_m0plus_codegen INTERFACE
    -ffunction-sections -fdata-sections
    --specs=nano.specs
    $<$<COMPILE_LANGUAGE:CXX>:-fno-threadsafe-statics -fno-use-cxa-atexit>
    -fstack-usage -fcallgraph-info=su
    -fmacro-prefix-map=${PROJECT_SOURCE_DIR}/=
    -Wno-psabi)
endif()

function(kestrel_m0plus_image target)
  kestrel_heap_guard(${target} j)  # ILP32
  target_link_options(${target} PRIVATE
    -nostartfiles
    --specs=nano.specs
    -T${KESTREL_M0PLUS_DIR}/rp2040_ram.ld
    -Wl,--gc-sections
    -Wl,--print-memory-usage
    "-Wl,-Map=$<TARGET_FILE:${target}>.map"
    -Wl,--cref)
  set_property(TARGET ${target} APPEND PROPERTY LINK_DEPENDS ${KESTREL_M0PLUS_DIR}/rp2040_ram.ld)
endfunction()
