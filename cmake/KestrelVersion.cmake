# SPDX-License-Identifier: Apache-2.0
# kestrel/version.hpp: KESTREL_VERSION_MAJOR/MINOR/PATCH and
# KESTREL_VERSION_STRING from project(kestrel VERSION ...), written into the
# build tree and put on kestrel::core's include path (the install puts it
# beside the core headers, cmake/KestrelInstall.cmake).
set(KESTREL_GENERATED_INCLUDE_DIR ${PROJECT_BINARY_DIR}/generated/include)
configure_file(${CMAKE_CURRENT_LIST_DIR}/version.hpp.in ${KESTREL_GENERATED_INCLUDE_DIR}/kestrel/version.hpp @ONLY)
target_include_directories(kestrel_core INTERFACE $<BUILD_INTERFACE:${KESTREL_GENERATED_INCLUDE_DIR}>)
