# Install the libraries, their headers and a CMake package: find_package(metricmap) gives
# metricmap::metricmap (everything); find_package(metricmap COMPONENTS core) looks only for what
# metricmap::core needs (PCL common + filters, Eigen).
include(CMakePackageConfigHelpers)

set(config_dir ${CMAKE_INSTALL_LIBDIR}/cmake/metricmap)
# One export set per component, so that the package config loads only the requested ones.
foreach(part core io mapping sequence posegraph slam slam3d distance localization)
  install(TARGETS metricmap_${part} EXPORT metricmap-${part}Targets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
    INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  install(EXPORT metricmap-${part}Targets NAMESPACE metricmap:: DESTINATION ${config_dir})
endforeach()
install(TARGETS metricmap EXPORT metricmapTargets)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/src/metricmap DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
  FILES_MATCHING PATTERN "*.h" PATTERN "*.hpp" PATTERN "distributed" EXCLUDE)
install(FILES ${PROJECT_BINARY_DIR}/src/generated/metricmap/version.h
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/metricmap)

install(EXPORT metricmapTargets NAMESPACE metricmap:: DESTINATION ${config_dir})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/metricmapConfig.cmake.in
  ${PROJECT_BINARY_DIR}/metricmapConfig.cmake INSTALL_DESTINATION ${config_dir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/metricmapConfigVersion.cmake
  COMPATIBILITY SameMajorVersion)
install(FILES ${PROJECT_BINARY_DIR}/metricmapConfig.cmake
              ${PROJECT_BINARY_DIR}/metricmapConfigVersion.cmake
  DESTINATION ${config_dir})
