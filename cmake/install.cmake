# Installation: the public headers, one exported target set per layer, and a package config
# with components, so that find_package(musclesim COMPONENTS model) needs only the model's
# dependencies (Eigen, NLopt) and never SUNDIALS or yaml-cpp.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(musclesim_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/musclesim)
install(DIRECTORY include/musclesim DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
foreach(layer ${MUSCLESIM_LAYERS})
  install(TARGETS musclesim_${layer} EXPORT musclesim_${layer}
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
    INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  install(EXPORT musclesim_${layer} NAMESPACE musclesim::
    FILE musclesim-${layer}-targets.cmake DESTINATION ${musclesim_cmake_dir})
endforeach()
install(TARGETS musclesim EXPORT musclesim_all)
install(EXPORT musclesim_all NAMESPACE musclesim::
  FILE musclesim-all-targets.cmake DESTINATION ${musclesim_cmake_dir})
if(MUSCLESIM_BUILD_CLI)
  install(TARGETS musclesim_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()

configure_package_config_file(cmake/musclesimConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/musclesimConfig.cmake INSTALL_DESTINATION ${musclesim_cmake_dir})
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/musclesimConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/musclesimConfig.cmake
  ${CMAKE_CURRENT_BINARY_DIR}/musclesimConfigVersion.cmake DESTINATION ${musclesim_cmake_dir})
