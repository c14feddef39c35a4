# SPDX-License-Identifier: Apache-2.0
# RISC-V 64 (RV64GC, LP64D ABI) embedded Linux: Debian's cross compiler
# (package g++-riscv64-linux-gnu). CPU/ABI only: the board's flags, static
# link and heap guard live in targets/riscv64-linux/. The target libraries
# (glibc, libstdc++) come with the compiler's sysroot; Eigen is header-only
# and is taken from the build machine, so no find root path is set.
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR riscv64)

set(CMAKE_C_COMPILER riscv64-linux-gnu-gcc)
set(CMAKE_CXX_COMPILER riscv64-linux-gnu-g++)

# The board links statically; probing with a static library keeps the
# compiler checks independent of the target's shared libraries.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

set(CMAKE_C_FLAGS_INIT "-march=rv64gc -mabi=lp64d")
set(CMAKE_CXX_FLAGS_INIT "-march=rv64gc -mabi=lp64d")
