# SPDX-License-Identifier: Apache-2.0
# Firmware evidence shared by every board (docs/footprint.md):
# the link-time heap guard, and the post-link size budget, forbidden-symbol
# check and worst-case stack budget of an image. Included by each board's
# CMakeLists.txt / image.cmake; not a board itself.
#
#   kestrel_board_common            INTERFACE library: targets/common/include
#                                   (KTRK track records, ring feed and sink,
#                                   DWT cycle clock).
#   kestrel_heap_symbols(<var> <j|m>)
#                                   every allocator entry point of newlib,
#                                   glibc and the C++ runtime; j = ILP32
#                                   (size_t is unsigned int), m = LP64
#                                   (unsigned long), the letter in the mangled
#                                   operator new/delete names.
#   kestrel_heap_guard(<target> <j|m>)
#                                   -Wl,--wrap=<sym> for each of them. No
#                                   __wrap_<sym> is ever defined, so any
#                                   reference fails the link naming its caller.
#   kestrel_board_evidence(<image> ...)
#                                   post-link size report with budgets,
#                                   symbol check, stack report with a budget,
#                                   JSON for the footprint table, and the
#                                   kestrel-evidence target that builds every
#                                   image of the board and nothing else.
include_guard(GLOBAL)

set(KESTREL_BOARD_COMMON_DIR ${CMAKE_CURRENT_LIST_DIR})

if(NOT TARGET kestrel_board_common)
  add_library(kestrel_board_common INTERFACE)
  target_include_directories(kestrel_board_common INTERFACE ${KESTREL_BOARD_COMMON_DIR}/include)
endif()

function(kestrel_heap_symbols out c)
  if(NOT c MATCHES "^[jm]$")
    message(FATAL_ERROR "kestrel_heap_symbols: the size_t mangling is j (ILP32) or m (LP64), not '${c}'")
  endif()
  set(syms
    # C allocator: newlib (plain and reentrant), glibc's internal names, the
    # break-pointer layer under them.
    malloc free calloc realloc reallocf reallocarray memalign aligned_alloc posix_memalign valloc pvalloc
    _malloc_r _free_r _calloc_r _realloc_r _reallocf_r _memalign_r _valloc_r _pvalloc_r
    __libc_malloc __libc_free __libc_calloc __libc_realloc __libc_memalign
    _sbrk _sbrk_r sbrk __sbrk brk __brk
    # Every global operator new/new[] and delete/delete[]: plain, nothrow,
    # aligned, sized.
    _Znw${c} _Zna${c} _Znw${c}RKSt9nothrow_t _Zna${c}RKSt9nothrow_t
    _Znw${c}St11align_val_t _Zna${c}St11align_val_t
    _Znw${c}St11align_val_tRKSt9nothrow_t _Zna${c}St11align_val_tRKSt9nothrow_t
    _ZdlPv _ZdaPv _ZdlPv${c} _ZdaPv${c} _ZdlPvRKSt9nothrow_t _ZdaPvRKSt9nothrow_t
    _ZdlPvSt11align_val_t _ZdaPvSt11align_val_t _ZdlPv${c}St11align_val_t _ZdaPv${c}St11align_val_t
    _ZdlPvSt11align_val_tRKSt9nothrow_t _ZdaPvSt11align_val_tRKSt9nothrow_t)
  set(${out} ${syms} PARENT_SCOPE)
endfunction()

function(kestrel_heap_guard target c)
  kestrel_heap_symbols(syms ${c})
  list(TRANSFORM syms PREPEND "--wrap=" OUTPUT_VARIABLE wraps)
  list(JOIN wraps "," wraps)
  target_link_options(${target} PRIVATE "-Wl,${wraps}")
endfunction()

# kestrel_board_evidence(<image target>
#     BOARD <board folder>          row of the footprint table
#     [LABEL <name>]                defaults to the image's output name
#     TEXT_BUDGET <bytes> DATA_BUDGET <bytes> BSS_BUDGET <bytes>
#     [STACK_BUDGET <bytes>]        worst chain from Tracker<...>::step
#     [MAIN_STACK_BUDGET <bytes>]   worst main stack of a Cortex-M image: the
#                                   reset chain plus one exception entry and
#                                   chain per handler of the vector table
#                                   (stack_report.py, "Main stack")
#     [FRAME_BUDGET <bytes>]        -Wstack-usage=<bytes> on every unit of
#                                   the image and of CI_TARGETS, and on its
#                                   link (code made by LTO): one frame
#                                   over it is a compile error (-Werror of
#                                   kestrel_firmware_flags)
#     [CI_TARGETS <target>...]      other targets whose objects are in the
#                                   image (their .ci call graphs are read)
#     [ROOTS <regex>...]            stack report roots (default: step,
#                                   firmware_main, IRQ handlers, reset,
#                                   static constructors)
#     [NO_SYMBOL_CHECK])            the image legitimately holds libc's heap
#                                   and stdio (a Linux process image): the
#                                   check runs on its heap-guard image instead
# Outputs in <build>/evidence/: <label>.size.txt/.json, <label>.stack.txt/.json.
function(kestrel_board_evidence image)
  cmake_parse_arguments(PARSE_ARGV 1 ev "NO_SYMBOL_CHECK"
    "BOARD;LABEL;TEXT_BUDGET;DATA_BUDGET;BSS_BUDGET;STACK_BUDGET;MAIN_STACK_BUDGET;FRAME_BUDGET" "CI_TARGETS;ROOTS")
  foreach(req BOARD TEXT_BUDGET DATA_BUDGET BSS_BUDGET)
    if(NOT DEFINED ev_${req})
      message(FATAL_ERROR "kestrel_board_evidence(${image}): ${req} is required")
    endif()
  endforeach()
  if(NOT ev_LABEL)
    set(ev_LABEL ${image})
  endif()
  string(REGEX REPLACE "\\.elf$" "" stem "${ev_LABEL}")

  # The binutils beside the nm CMake found for the toolchain.
  get_filename_component(bindir "${CMAKE_NM}" DIRECTORY)
  get_filename_component(nm_name "${CMAKE_NM}" NAME)
  string(REGEX REPLACE "nm$" "size" size_name "${nm_name}")
  find_program(KESTREL_SIZE_TOOL NAMES ${size_name} HINTS ${bindir} NO_DEFAULT_PATH)
  find_program(KESTREL_SIZE_TOOL NAMES ${size_name} REQUIRED)

  set(dir ${CMAKE_BINARY_DIR}/evidence)
  file(MAKE_DIRECTORY ${dir})
  set(elf $<TARGET_FILE:${image}>)

  if(DEFINED ev_FRAME_BUDGET)
    foreach(t ${image} ${ev_CI_TARGETS})
      target_compile_options(${t} PRIVATE -Wstack-usage=${ev_FRAME_BUDGET})
    endforeach()
    # With link-time optimisation the frames are made at the link.
    target_link_options(${image} PRIVATE -Wstack-usage=${ev_FRAME_BUDGET})
  endif()

  set(cmds
    COMMAND ${CMAKE_COMMAND} -DSIZE=${KESTREL_SIZE_TOOL} -DELF=${elf}
            -DOUT=${dir}/${stem}.size.txt -DJSON=${dir}/${stem}.size.json -DLABEL=${ev_LABEL}
            -DBOARD=${ev_BOARD} -DBUILD_TYPE=${CMAKE_BUILD_TYPE}
            -DTEXT_BUDGET=${ev_TEXT_BUDGET} -DDATA_BUDGET=${ev_DATA_BUDGET} -DBSS_BUDGET=${ev_BSS_BUDGET}
            -P ${KESTREL_BOARD_COMMON_DIR}/size_report.cmake)
  if(NOT ev_NO_SYMBOL_CHECK)
    list(APPEND cmds
      COMMAND ${CMAKE_COMMAND} -DNM=${CMAKE_NM} -DELF=${elf} -P ${KESTREL_BOARD_COMMON_DIR}/check_symbols.cmake)
  endif()

  find_package(Python3 COMPONENTS Interpreter QUIET)
  if(DEFINED ev_STACK_BUDGET AND NOT Python3_Interpreter_FOUND)
    message(WARNING "Python 3 not found: no stack report or stack budget check for ${image}")
  elseif(DEFINED ev_STACK_BUDGET)
    set(stack_args --objdump ${CMAKE_OBJDUMP} --elf ${elf}
        --ci-dir $<TARGET_PROPERTY:${image},BINARY_DIR>/CMakeFiles/${image}.dir)
    foreach(t IN LISTS ev_CI_TARGETS)
      list(APPEND stack_args --ci-dir $<TARGET_PROPERTY:${t},BINARY_DIR>/CMakeFiles/${t}.dir)
    endforeach()
    foreach(r IN LISTS ev_ROOTS)
      list(APPEND stack_args --root ${r})
    endforeach()
    if(DEFINED ev_MAIN_STACK_BUDGET)
      list(APPEND stack_args --main-budget ${ev_MAIN_STACK_BUDGET})
    endif()
    list(APPEND stack_args --budget ${ev_STACK_BUDGET} --label ${ev_LABEL}
         --out ${dir}/${stem}.stack.txt --json ${dir}/${stem}.stack.json)
    list(APPEND cmds COMMAND Python3::Interpreter ${KESTREL_BOARD_COMMON_DIR}/stack_report.py ${stack_args} --reject)
    # On demand, e.g. after reading a map file: print the report again.
    add_custom_target(${stem}-stack-report
      COMMAND Python3::Interpreter ${KESTREL_BOARD_COMMON_DIR}/stack_report.py ${stack_args}
      DEPENDS ${image}
      COMMENT "Worst-case stack of the ${ev_LABEL} call chains -> evidence/${stem}.stack.txt"
      VERBATIM)
  endif()

  add_custom_command(TARGET ${image} POST_BUILD ${cmds}
    COMMENT "${ev_LABEL}: size budget, forbidden-symbol check, stack budget (-> evidence/)"
    VERBATIM)

  if(NOT TARGET kestrel-evidence)
    add_custom_target(kestrel-evidence COMMENT "Board images and their evidence are up to date (build/<preset>/evidence)")
  endif()
  add_dependencies(kestrel-evidence ${image})
endfunction()
