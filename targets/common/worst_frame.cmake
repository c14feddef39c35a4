# SPDX-License-Identifier: Apache-2.0
# kestrel_worst_frame_program(CODEGEN <library> NAMESPACE <board namespace>
#                             BOARD <name> [CONSTEXPR_SCALARS] [SOURCES <file>...]
#                             [LINK_OPTIONS <option>...]):
# the worst-case frame program (tests/targets/worst_frame/) with the board's
# own board.hpp, code generation and kestrel::core's flags, linked as a
# Linux user-mode program for qemu-arm / qemu-riscv64. Not part of the
# image (EXCLUDE_FROM_ALL); CTest's <board>_frame_budget builds it in the
# board's tree and counts its frames (tests/targets/frame_budget.py).
# CONSTEXPR_SCALARS: the board's main.cpp converts the tracker parameters
# at compile time (the fixed-point board), so the program does as well.
include_guard(GLOBAL)

function(kestrel_worst_frame_program)
  cmake_parse_arguments(WF "CONSTEXPR_SCALARS" "CODEGEN;NAMESPACE;BOARD" "SOURCES;LINK_OPTIONS" ${ARGN})
  set(dir ${PROJECT_SOURCE_DIR}/tests/targets/worst_frame)
  add_executable(kestrel-worst-frame EXCLUDE_FROM_ALL ${dir}/worst_frame.cpp ${WF_SOURCES})
  target_include_directories(kestrel-worst-frame PRIVATE ${CMAKE_CURRENT_SOURCE_DIR} ${PROJECT_SOURCE_DIR}/tests)
  target_compile_definitions(kestrel-worst-frame PRIVATE KESTREL_WF_NS=kestrel::${WF_NAMESPACE}
                                                         KESTREL_WF_BOARD="${WF_BOARD}")
  if(WF_CONSTEXPR_SCALARS)
    target_compile_definitions(kestrel-worst-frame PRIVATE KESTREL_WF_CONSTEXPR_SCALARS)
  endif()
  target_link_libraries(kestrel-worst-frame PRIVATE kestrel::core kestrel::hal kestrel_board_common
                                                    kestrel_firmware_flags ${WF_CODEGEN})
  target_link_options(kestrel-worst-frame PRIVATE ${WF_LINK_OPTIONS})
endfunction()
