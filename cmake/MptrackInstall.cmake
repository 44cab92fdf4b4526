# `cmake --install` of the core (README.md "Using mptrack from CMake"):
# the headers, the float/double instantiation library (mptrack::core_static),
# the C API (mptrack::c) and an exported package, mptrackConfig.cmake with
# mptrackConfigVersion.cmake, whose targets carry the flags they were built
# with (mptrack::deterministic: -ffp-contract=off, EIGEN_DONT_VECTORIZE and
# the CPU flags of the toolchain file), so a consumer compiles the headers
# the way the library was compiled. Eigen is found as a dependency.
include(CMakePackageConfigHelpers)
set(MPTRACK_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/mptrack CACHE STRING
    "Where mptrackConfig.cmake is installed, relative to the prefix")

set_target_properties(mptrack_core PROPERTIES EXPORT_NAME core)
set_target_properties(mptrack_core_static PROPERTIES EXPORT_NAME core_static)
set_target_properties(mptrack_c PROPERTIES EXPORT_NAME c)
set_target_properties(mptrack_deterministic PROPERTIES EXPORT_NAME deterministic)
set_target_properties(mptrack_warnings PROPERTIES EXPORT_NAME warnings)
set_target_properties(mptrack_embedded PROPERTIES EXPORT_NAME embedded)
set_target_properties(mptrack_sanitize PROPERTIES EXPORT_NAME sanitize)

# warnings and embedded are PRIVATE to the libraries; exported because a
# static library lists them as link-only dependencies (they add no flags
# to a consumer's compile).
install(TARGETS mptrack_core mptrack_core_static mptrack_c mptrack_deterministic mptrack_warnings
                mptrack_embedded mptrack_sanitize
  EXPORT mptrackTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/core/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT mptrackTargets NAMESPACE mptrack:: DESTINATION ${MPTRACK_INSTALL_CMAKEDIR})

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/mptrackConfig.cmake.in
  ${PROJECT_BINARY_DIR}/mptrackConfig.cmake INSTALL_DESTINATION ${MPTRACK_INSTALL_CMAKEDIR})
# 0.x: a minor version may break the API, so only the same minor matches.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/mptrackConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/mptrackConfig.cmake ${PROJECT_BINARY_DIR}/mptrackConfigVersion.cmake
  DESTINATION ${MPTRACK_INSTALL_CMAKEDIR})
