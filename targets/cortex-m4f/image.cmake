# How an STM32F407 (Cortex-M4F) image is compiled and linked. Included by
# targets/cortex-m4f/CMakeLists.txt for the firmware and by the heap-guard
# probe project of tests/targets, so the negative test exercises exactly the
# options the firmware links with.
#
#   kestrel_m4f_codegen   INTERFACE library: code generation flags for every
#                         translation unit in the image.
#   kestrel_m4f_image(<executable>)
#                         linker script, start-up model, --gc-sections, map
#                         file, memory-usage print, and the heap guard.
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

# Allocation entry points: newlib (plain and reentrant), the sbrk layer
# under them, and every global operator new/delete of the ILP32 ABI
# (size_t = unsigned int -> 'j' in the mangled names).
set(KESTREL_M4F_HEAP_SYMBOLS
  malloc free calloc realloc reallocf memalign aligned_alloc posix_memalign valloc pvalloc
  _malloc_r _free_r _calloc_r _realloc_r _reallocf_r _memalign_r _valloc_r _pvalloc_r
  _sbrk _sbrk_r
  _Znwj _Znaj _ZnwjRKSt9nothrow_t _ZnajRKSt9nothrow_t
  _ZnwjSt11align_val_t _ZnajSt11align_val_t
  _ZnwjSt11align_val_tRKSt9nothrow_t _ZnajSt11align_val_tRKSt9nothrow_t
  _ZdlPv _ZdaPv _ZdlPvj _ZdaPvj _ZdlPvRKSt9nothrow_t _ZdaPvRKSt9nothrow_t
  _ZdlPvSt11align_val_t _ZdaPvSt11align_val_t _ZdlPvjSt11align_val_t _ZdaPvjSt11align_val_t
  _ZdlPvSt11align_val_tRKSt9nothrow_t _ZdaPvSt11align_val_tRKSt9nothrow_t)

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
endif()

function(kestrel_m4f_image target)
  list(TRANSFORM KESTREL_M4F_HEAP_SYMBOLS PREPEND "--wrap=" OUTPUT_VARIABLE wraps)
  list(JOIN wraps "," wraps)
  target_link_options(${target} PRIVATE
    -nostartfiles                      # startup.cpp is the whole start-up
    --specs=nano.specs                 # newlib-nano libc and libstdc++
    -T${KESTREL_M4F_DIR}/stm32f407.ld
    -Wl,--gc-sections
    -Wl,--print-memory-usage
    "-Wl,-Map=$<TARGET_FILE:${target}>.map"
    -Wl,--cref
    "-Wl,${wraps}")
  set_property(TARGET ${target} APPEND PROPERTY LINK_DEPENDS ${KESTREL_M4F_DIR}/stm32f407.ld)
endfunction()
