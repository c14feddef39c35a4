# SPDX-License-Identifier: Apache-2.0
# RISC-V 32 bare metal (default RV32IMAFC, ILP32F ABI: a single-precision
# FPU, so the float build, as on the Cortex-M4F), for a GNU toolchain that
# ships a C++ library: riscv-gnu-toolchain built with newlib
# (riscv32-unknown-elf-), xPack's riscv-none-elf-, SiFive's
# riscv64-unknown-elf- with rv32 multilibs, a vendor SDK. Debian ships
# gcc-riscv64-unknown-elf and picolibc but no libstdc++ for it, so this file
# cannot be exercised on the project's machines (docs/porting.md, "RISC-V").
# CPU/ABI only; a board folder brings the linker script, start-up and heap
# guard (kestrel_heap_guard(<image> j): ILP32 mangling).
#
# Choose another toolchain prefix or core on the command line, e.g.
#   cmake -S . -B build/rv32 --toolchain toolchains/riscv32-unknown-elf.cmake \
#         -DKESTREL_RISCV32_PREFIX=riscv-none-elf- -DKESTREL_RISCV32_ARCH=rv32imac \
#         -DKESTREL_RISCV32_ABI=ilp32 -DKESTREL_BOARD=<your board>
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR riscv32)

set(KESTREL_RISCV32_PREFIX "riscv32-unknown-elf-" CACHE STRING "Prefix of the RISC-V bare-metal GNU tools")
set(KESTREL_RISCV32_ARCH "rv32imafc" CACHE STRING "-march of the core (rv32imac: no FPU)")
set(KESTREL_RISCV32_ABI "ilp32f" CACHE STRING "-mabi matching the -march (ilp32 without F)")
# try_compile projects re-read this file with a fresh cache: pass the choices on.
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES KESTREL_RISCV32_PREFIX KESTREL_RISCV32_ARCH KESTREL_RISCV32_ABI)

set(CMAKE_C_COMPILER ${KESTREL_RISCV32_PREFIX}gcc)
set(CMAKE_CXX_COMPILER ${KESTREL_RISCV32_PREFIX}g++)
set(CMAKE_ASM_COMPILER ${KESTREL_RISCV32_PREFIX}gcc)

# No startup files or linker script exist at try-compile time.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

set(CMAKE_C_FLAGS_INIT "-march=${KESTREL_RISCV32_ARCH} -mabi=${KESTREL_RISCV32_ABI} -mcmodel=medlow")
set(CMAKE_CXX_FLAGS_INIT "-march=${KESTREL_RISCV32_ARCH} -mabi=${KESTREL_RISCV32_ABI} -mcmodel=medlow")
set(CMAKE_ASM_FLAGS_INIT "-march=${KESTREL_RISCV32_ARCH} -mabi=${KESTREL_RISCV32_ABI} -mcmodel=medlow")
