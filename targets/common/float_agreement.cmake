# SPDX-License-Identifier: Apache-2.0
# kestrel_float_agreement_program(<codegen library>): the float tracker's
# agreement program (tests/targets/float_agreement/) built with a Cortex-M
# board's own code generation and kestrel::core's flags, but linked as a
# program that qemu-arm's Linux user mode runs: no linker script, no start
# files. Not part of the image (EXCLUDE_FROM_ALL); the host build's CTest
# builds it in the board's tree and compares its output with the host's.
include_guard(GLOBAL)

function(kestrel_float_agreement_program codegen)
  set(dir ${PROJECT_SOURCE_DIR}/tests/targets/float_agreement)
  add_executable(kestrel-float-agreement EXCLUDE_FROM_ALL ${dir}/float_agreement.cpp)
  target_include_directories(kestrel-float-agreement PRIVATE ${PROJECT_SOURCE_DIR}/tests)
  target_link_libraries(kestrel-float-agreement PRIVATE kestrel::core kestrel::hal kestrel_firmware_flags ${codegen})
  target_link_options(kestrel-float-agreement PRIVATE -nostartfiles --specs=nano.specs)
endfunction()
