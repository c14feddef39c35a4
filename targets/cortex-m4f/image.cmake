# SPDX-License-Identifier: Apache-2.0
# How an STM32F407 (Cortex-M4F) image is compiled and linked. Included by
# targets/cortex-m4f/CMakeLists.txt for the firmware and by the heap-guard
# probe project of tests/targets, so the negative test exercises exactly the
# options the firmware links with.
#
#   kestrel_m4f_codegen   INTERFACE library: code generation flags for every
#                         translation unit in the image.
#   kestrel_m4f_image(<executable>)
#                         link-time optimisation, linker script, start-up
#                         model, --gc-sections, map file, memory-usage
#                         print, and the heap guard.
#
# The heap guard: every allocator entry point of newlib and of the C++
# runtime is --wrap'ed, and no __wrap_<name> is ever defined. The linker then
# redirects each reference to malloc (or operator new, _sbrk, ...) to an
# undefined __wrap_<name>, and the link fails with
#   <caller.o>:(.text.<caller>): undefined reference to `__wrap_malloc'
# naming the caller. This also catches heap use hidden inside libc/libstdc++
# members (printf -> _malloc_r, __cxa_allocate_exception -> malloc), because
# --wrap applies to every input object, archives included.
include_guard(GLOBAL)

set(KESTREL_M4F_DIR ${CMAKE_CURRENT_LIST_DIR})

# Allocation entry points (newlib, glibc, every global operator new/delete
# of the ILP32 ABI: size_t = unsigned int -> 'j' in the mangled names) and
# the guard itself: targets/common/evidence.cmake, shared by every board.
include(${CMAKE_CURRENT_LIST_DIR}/../common/evidence.cmake)

if(NOT TARGET kestrel_m4f_codegen)
  add_library(kestrel_m4f_codegen INTERFACE)
  target_compile_options(kestrel_m4f_codegen INTERFACE
    # One section per function and object, so --gc-sections drops what is unused.
    -ffunction-sections -fdata-sections
    # newlib-nano headers, matching the libraries linked below.
    --specs=nano.specs
    # No guard variables or atexit registration for statics: there are no
    # threads, and destructors of statics never run (main does not return).
    $<$<COMPILE_LANGUAGE:CXX>:-fno-threadsafe-statics -fno-use-cxa-atexit>
    # Per-function stack usage (.su) and call graph with it (.ci) next to
    # each object: input of stack_report.py (docs/footprint.md).
    -fstack-usage -fcallgraph-info=su
    # __FILE__ in assertion records relative to the source tree.
    -fmacro-prefix-map=${PROJECT_SOURCE_DIR}/=
    # GCC's note that passing some Eigen structs by value changed ABI in
    # GCC 7.1: irrelevant when the whole image is built by one compiler.
    -Wno-psabi)
  # Eigen loops instead of complete unrolling: at -Os a completely unrolled
  # 6x6 assignment or reduction is straight-line code per instantiation
  # (docs/footprint.md, "2026-12-03"). Unrolled reductions add in a
  # pairwise tree and the loops from left to right, so sums of three or more
  # terms may round differently from the host's (the board's float tests
  # compare within tolerances, not bits).
  target_compile_definitions(kestrel_m4f_codegen INTERFACE EIGEN_UNROLLING_LIMIT=0)
endif()

function(kestrel_m4f_image target)
  kestrel_heap_guard(${target} j)
  # Link-time optimisation in one partition: the sources of <executable>
  # (and of any library built with -flto, kestrel_hal on this board) are
  # optimised as one unit, so template code used once is inlined or
  # dropped and every function not reached from outside becomes local.
  # Compiling with -flto writes no .su/.ci; code is generated at the link,
  # which therefore takes the per-function stack usage and call graph
  # options (written as ltrans0.ltrans.{su,ci} into the object directory,
  # where stack_report.py reads them) and -Werror (the frame budget's
  # -Wstack-usage is checked there too, targets/common/evidence.cmake).
  target_compile_options(${target} PRIVATE -flto)
  target_link_options(${target} PRIVATE
    -flto -flto-partition=one -fstack-usage -fcallgraph-info=su -Werror
    "-dumpdir" "$<TARGET_PROPERTY:${target},BINARY_DIR>/CMakeFiles/${target}.dir/")
  target_link_options(${target} PRIVATE
    -nostartfiles                      # startup.cpp is the whole start-up
    --specs=nano.specs                 # newlib-nano libc and libstdc++
    -T${KESTREL_M4F_DIR}/stm32f407.ld
    -Wl,--gc-sections
    -Wl,--print-memory-usage
    "-Wl,-Map=$<TARGET_FILE:${target}>.map"
    -Wl,--cref)
  set_property(TARGET ${target} APPEND PROPERTY LINK_DEPENDS ${KESTREL_M4F_DIR}/stm32f407.ld)
endfunction()
