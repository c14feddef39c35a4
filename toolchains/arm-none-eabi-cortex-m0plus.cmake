# SPDX-License-Identifier: Apache-2.0
# Cortex-M0+ (ARMv6-M, no FPU), bare metal, soft-float ABI. CPU/ABI only:
# the board's flags, linker script and heap guard live in
# targets/cortex-m0plus/. The driver picks the thumb/v6-m/nofp multilib of
# newlib and libstdc++; every float operation is a libgcc routine.
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)

set(CMAKE_C_COMPILER arm-none-eabi-gcc)
set(CMAKE_CXX_COMPILER arm-none-eabi-g++)
set(CMAKE_ASM_COMPILER arm-none-eabi-gcc)

# No startup files or linker script exist at try-compile time.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

set(CMAKE_C_FLAGS_INIT "-mcpu=cortex-m0plus -mthumb -mfloat-abi=soft")
set(CMAKE_CXX_FLAGS_INIT "-mcpu=cortex-m0plus -mthumb -mfloat-abi=soft")
set(CMAKE_ASM_FLAGS_INIT "-mcpu=cortex-m0plus -mthumb -mfloat-abi=soft")
