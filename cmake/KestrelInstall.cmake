# SPDX-License-Identifier: Apache-2.0
# cmake --install: the core and hal headers (with the generated
# kestrel/version.hpp), libkestrel_hal.a, and the CMake package
#   <libdir>/cmake/kestrel/kestrelConfig.cmake         find_dependency(Eigen3 3.4)
#   <libdir>/cmake/kestrel/kestrelConfigVersion.cmake  same major.minor (0.x)
#   <libdir>/cmake/kestrel/kestrelTargets*.cmake       kestrel::core, kestrel::hal
# and the licence. What an imported kestrel::core carries (C++20,
# -ffp-contract=off, EIGEN_GEMM_TO_COEFFBASED_THRESHOLD, Eigen3::Eigen) and
# what it does not (kestrel_firmware_flags): docs/integration.md.
include(CMakePackageConfigHelpers)

set(KESTREL_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/kestrel CACHE STRING
    "Where the kestrel CMake package goes, relative to the install prefix")
mark_as_advanced(KESTREL_INSTALL_CMAKEDIR)

set_target_properties(kestrel_core PROPERTIES EXPORT_NAME core)
set_target_properties(kestrel_hal PROPERTIES EXPORT_NAME hal)

install(DIRECTORY ${PROJECT_SOURCE_DIR}/core/include/ ${PROJECT_SOURCE_DIR}/hal/include/
                  ${KESTREL_GENERATED_INCLUDE_DIR}/
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        COMPONENT kestrel_development
        FILES_MATCHING PATTERN "*.hpp")
install(TARGETS kestrel_core kestrel_hal
        EXPORT kestrelTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT kestrel_development)
install(EXPORT kestrelTargets
        NAMESPACE kestrel::
        DESTINATION ${KESTREL_INSTALL_CMAKEDIR}
        COMPONENT kestrel_development)

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/kestrelConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/kestrelConfig.cmake
                              INSTALL_DESTINATION ${KESTREL_INSTALL_CMAKEDIR})
# 0.x: a minor release may break the API, so 0.1 accepts 0.1.* only.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/kestrelConfigVersion.cmake
                                 VERSION ${PROJECT_VERSION}
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/kestrelConfig.cmake ${PROJECT_BINARY_DIR}/kestrelConfigVersion.cmake
        DESTINATION ${KESTREL_INSTALL_CMAKEDIR}
        COMPONENT kestrel_development)
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE
        DESTINATION ${CMAKE_INSTALL_DATADIR}/licenses/kestrel
        COMPONENT kestrel_development)
