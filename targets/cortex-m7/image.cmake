# SPDX-License-Identifier: Apache-2.0
# How an STM32H743 (Cortex-M7) image is compiled and linked. Included by
# targets/cortex-m7/CMakeLists.txt for the firmware and by the heap-guard
# probe project of tests/targets, so the negative test exercises exactly the
# options the firmware links with. Same model as the Cortex-M4F board
# (targets/cortex-m4f/image.cmake, where each flag is explained in
# docs/porting.md); only the linker script differs.
#
#   kestrel_m7_codegen   INTERFACE library: code generation flags for every
#                        translation unit in the image.
#   kestrel_m7_image(<executable>)
#                        linker script, start-up model, --gc-sections, map
#                        file, memory-usage print, and the heap guard
#                        (kestrel_heap_guard, targets/common/evidence.cmake:
#                        every allocator --wrap'ed to an undefined symbol).
include_guard(GLOBAL)

set(KESTREL_M7_DIR ${CMAKE_CURRENT_LIST_DIR})
include(${CMAKE_CURRENT_LIST_DIR}/../common/evidence.cmake)

if(NOT TARGET kestrel_m7_codegen)
  add_library(kestrel_m7_codegen INTERFACE)
  target_compile_options(kestrel_m7_codegen INTERFACE
    -ffunction-sections -fdata-sections
    --specs=nano.specs
    $<$<COMPILE_LANGUAGE:CXX>:-fno-threadsafe-statics -fno-use-cxa-atexit>
    -fstack-usage -fcallgraph-info=su
    -fmacro-prefix-map=${PROJECT_SOURCE_DIR}/=
    -Wno-psabi)
endif()

function(kestrel_m7_image target)
  kestrel_heap_guard(${target} j)  # ILP32: size_t = unsigned int
  target_link_options(${target} PRIVATE
    -nostartfiles
    --specs=nano.specs
    -T${KESTREL_M7_DIR}/stm32h743.ld
    -Wl,--gc-sections
    -Wl,--print-memory-usage
    "-Wl,-Map=$<TARGET_FILE:${target}>.map"
    -Wl,--cref)
  set_property(TARGET ${target} APPEND PROPERTY LINK_DEPENDS ${KESTREL_M7_DIR}/stm32h743.ld)
endfunction()
