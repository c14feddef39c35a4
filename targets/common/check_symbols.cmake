# SPDX-License-Identifier: Apache-2.0
# Post-link symbol check of an image: cmake -DNM=<binutils nm>
#   -DELF=<image> -P check_symbols.cmake
# Fails if the symbol table names anything from the heap (malloc family,
# _sbrk, operator new/delete), stdio output (the printf and puts families,
# _write) or C++ exception throwing (__cxa_throw, the unwinder, the
# std::__throw_* helpers), and renames the image to <image>.rejected so the
# failure repeats on the next build and nobody flashes it. The link-time
# heap guard (kestrel_heap_guard in evidence.cmake; each board's image.cmake)
# should already have refused all heap symbols; this is the second net and
# the only one for stdio and exceptions. Every board runs it on the image
# that holds the tracker's code path (on riscv64-linux: the heap-guard image,
# since glibc's start-up in the process image has its own malloc and stdio).
#
# It also lists, without failing, the double-precision soft-float helpers
# and the libm functions in the image: on a single-precision FPU each of
# them is a software routine, so their presence in a float build is worth
# knowing (docs/footprint.md).
cmake_minimum_required(VERSION 3.25)

foreach(var NM ELF)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "check_symbols.cmake: -D${var}=... is required")
  endif()
endforeach()
if(NOT EXISTS ${ELF})
  message(FATAL_ERROR "check_symbols.cmake: ${ELF} does not exist")
endif()

execute_process(COMMAND ${NM} -S --size-sort ${ELF} RESULT_VARIABLE rc OUTPUT_VARIABLE sized ERROR_VARIABLE err)
execute_process(COMMAND ${NM} ${ELF} RESULT_VARIABLE rc2 OUTPUT_VARIABLE all ERROR_VARIABLE err2)
if(NOT rc EQUAL 0 OR NOT rc2 EQUAL 0)
  message(FATAL_ERROR "check_symbols.cmake: ${NM} failed on ${ELF}: ${err}${err2}")
endif()

# Every symbol name, defined or not ("addr type name" or "U name").
string(REPLACE "\n" ";" lines "${all}")
set(names "")
foreach(line IN LISTS lines)
  if(line MATCHES "^[0-9a-fA-F ]* [A-Za-z?] ([^ ]+)$")
    # A function cloned or localised by the optimiser (link-time
    # optimisation in particular) keeps its name before a suffix such as
    # .constprop.0, .isra.0, .part.0 or .lto_priv.0: check that name.
    string(REGEX REPLACE "^([^.]+)\\..*$" "\\1" name "${CMAKE_MATCH_1}")
    list(APPEND names "${name}")
  endif()
endforeach()

set(forbidden_exact
  # heap
  malloc free calloc realloc reallocf memalign aligned_alloc posix_memalign valloc pvalloc
  _malloc_r _free_r _calloc_r _realloc_r _reallocf_r _memalign_r _sbrk _sbrk_r
  __libc_malloc __libc_free __libc_calloc __libc_realloc __libc_memalign reallocarray  # glibc
  sbrk __sbrk brk __brk
  # stdio output
  printf fprintf sprintf snprintf vprintf vfprintf vsprintf vsnprintf asprintf dprintf
  iprintf fiprintf siprintf sniprintf viprintf vfiprintf vsiprintf vsniprintf
  _printf_r _fprintf_r _sprintf_r _snprintf_r _vfprintf_r _svfprintf_r _vfiprintf_r _svfiprintf_r
  _iprintf_r _vsnprintf_r _vsprintf_r
  puts fputs putchar fputc putc fwrite _puts_r _fputs_r _putchar_r _fputc_r _fwrite_r
  __sfvwrite_r __swbuf_r __swsetup_r _write _write_r
  # exceptions
  __cxa_throw __cxa_rethrow __cxa_allocate_exception __cxa_free_exception __cxa_begin_catch
  __cxa_end_catch __gxx_personality_v0 _Unwind_RaiseException _Unwind_Resume _Unwind_Backtrace
  # static destructors registered at run time (never run on this board)
  atexit __cxa_atexit __register_exitproc)
set(forbidden_regex
  "^_Zn[wa]"            # operator new, new[]
  "^_Zd[la]"            # operator delete, delete[]
  "^__wrap_"            # a heap-guard wrapper somebody defined to get around the guard
  "^_ZSt[0-9]+__throw_" # std::__throw_bad_alloc, __throw_out_of_range, ...
  "^_ZNSt[0-9]*ios_base" "^_ZSt4cout" "^_ZSt4cerr")  # iostreams

set(found "")
foreach(name IN LISTS names)
  if(name IN_LIST forbidden_exact)
    list(APPEND found "${name}")
    continue()
  endif()
  foreach(re IN LISTS forbidden_regex)
    if(name MATCHES "${re}")
      list(APPEND found "${name}")
      break()
    endif()
  endforeach()
endforeach()

# Informational: double-precision soft-float helpers and libm routines.
set(notes "")
string(REPLACE "\n" ";" sized_lines "${sized}")
foreach(line IN LISTS sized_lines)
  if(line MATCHES "^[0-9a-fA-F]+ ([0-9a-fA-F]+) [A-Za-z] ([^ ]+)$")
    set(name "${CMAKE_MATCH_2}")
    math(EXPR bytes "0x${CMAKE_MATCH_1}" OUTPUT_FORMAT DECIMAL)
    if(name MATCHES "^__aeabi_(d|[iu]?[il]2d|f2d|l2d|ul2d)"
       OR name MATCHES "^__(add|sub|mul|div|neg|extendsf|truncdfsf|fix|fixuns|float|floatun|eq|ne|lt|le|gt|ge|unord|cmp)(df|sidf|didf|disf|sfdf)"
       OR name MATCHES "^__ieee754_" OR name MATCHES "^__kernel_"
       OR name MATCHES "^(sin|cos|tan|asin|acos|atan|atan2|hypot|sqrt|exp|log|pow|fmod|remainder|floor|ceil|round|nearbyint|rint|scalbn|copysign|fabs|finite|isnan|isinf)f?$")
      string(APPEND notes "--   ${bytes}\t${name}\n")
    endif()
  endif()
endforeach()
if(notes)
  message(STATUS "Soft-float double helpers and libm routines in ${ELF} (size, name):\n${notes}")
endif()

if(found)
  list(REMOVE_DUPLICATES found)
  list(JOIN found "\n  " found_text)
  file(RENAME ${ELF} ${ELF}.rejected)
  message(FATAL_ERROR "check_symbols.cmake: ${ELF} contains forbidden symbols "
                      "(heap, stdio or exceptions):\n  ${found_text}\n"
                      "The image was renamed to ${ELF}.rejected. Find who pulls them in with the "
                      "cross-reference table of the map file (-Wl,--cref).")
endif()
message(STATUS "check_symbols.cmake: no heap, stdio or exception symbols in ${ELF}")
