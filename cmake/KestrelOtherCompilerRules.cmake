# SPDX-License-Identifier: Apache-2.0
# The firmware rules (kestrel_firmware_flags) under the other host compiler:
# g++ when the build is clang's, clang++ when it is GCC's. Core and hal must
# build with both: the boards' compilers are GCC, the host build and the
# sanitizers clang. Front end only (-fsyntax-only): exceptions, RTTI and the
# warning wall are front-end checks, and the build's own compiler already
# compiles every rules-check object in full (kestrel_core_rules_check).
# Every core/src/*_rules_check.cpp and hal/src/*.cpp, one stamp each, in the
# default build (target kestrel_other_compiler_rules_check).
if(CMAKE_CXX_COMPILER_ID MATCHES "Clang")
  find_program(KESTREL_OTHER_CXX NAMES g++ DOC "GCC for the other-compiler rules check")
elseif(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
  find_program(KESTREL_OTHER_CXX NAMES clang++ DOC "clang for the other-compiler rules check")
endif()
if(NOT KESTREL_OTHER_CXX)
  message(STATUS "Kestrel: no other host compiler found; the other-compiler rules check is skipped")
  return()
endif()

file(GLOB _kestrel_rules_sources CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/core/src/*rules_check.cpp
     ${PROJECT_SOURCE_DIR}/hal/src/*.cpp)
set(_kestrel_rules_stamps)
foreach(src ${_kestrel_rules_sources})
  get_filename_component(stem ${src} NAME_WE)
  set(stamp ${CMAKE_CURRENT_BINARY_DIR}/other_compiler_rules_${stem}.ok)
  add_custom_command(OUTPUT ${stamp}
    COMMAND ${KESTREL_OTHER_CXX} -std=c++20 -fsyntax-only
            -I${PROJECT_SOURCE_DIR}/core/include -I${PROJECT_SOURCE_DIR}/hal/include -I${KESTREL_GENERATED_INCLUDE_DIR}
            -isystem ${EIGEN3_INCLUDE_DIR}
            -DEIGEN_NO_MALLOC -DEIGEN_GEMM_TO_COEFFBASED_THRESHOLD=4096 -DNDEBUG -ffp-contract=off
            -fno-exceptions -fno-rtti -fno-math-errno ${KESTREL_FIRMWARE_WARNINGS} -Wold-style-cast -Werror ${src}
    COMMAND ${CMAKE_COMMAND} -E touch ${stamp}
    DEPENDS ${src}
    IMPLICIT_DEPENDS CXX ${src}
    COMMENT "Rules check of ${stem} under ${KESTREL_OTHER_CXX}"
    VERBATIM)
  list(APPEND _kestrel_rules_stamps ${stamp})
endforeach()
add_custom_target(kestrel_other_compiler_rules_check ALL DEPENDS ${_kestrel_rules_stamps})
