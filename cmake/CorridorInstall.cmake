# Install rules and an exported CMake package: research code writes
#   find_package(corridor_depth REQUIRED)
#   target_link_libraries(app PRIVATE corridor_depth::core)
# and includes <corridor_depth/corridor_depth.h>. Only the library is installed: its module
# libraries and the public headers of include/corridor_depth/. The tools' helpers, the generator,
# the ROS bag code and the private headers are not.
include(CMakePackageConfigHelpers)

# The modules of corridor_depth::core, in dependency order: OpenCV, Eigen, Ceres (with glog) and
# yaml-cpp only; no gflags, no ROS.
set(CORRIDOR_CORE_MODULES corridor_core corridor_io corridor_kernels corridor_perception
    corridor_estimation corridor_depth_planes corridor_pipeline corridor_evaluation)
add_library(corridor_depth_core INTERFACE)
target_link_libraries(corridor_depth_core INTERFACE ${CORRIDOR_CORE_MODULES})
set_target_properties(corridor_depth_core PROPERTIES EXPORT_NAME core)
add_library(corridor_depth::core ALIAS corridor_depth_core)

install(TARGETS ${CORRIDOR_CORE_MODULES} corridor_depth_core
  EXPORT corridor_depthTargets
  ARCHIVE DESTINATION lib
  LIBRARY DESTINATION lib
  RUNTIME DESTINATION bin)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/corridor_depth DESTINATION include
        FILES_MATCHING PATTERN "*.h")
install(EXPORT corridor_depthTargets
  NAMESPACE corridor_depth::
  DESTINATION lib/cmake/corridor_depth)
configure_package_config_file(
  ${PROJECT_SOURCE_DIR}/cmake/corridor_depthConfig.cmake.in
  ${PROJECT_BINARY_DIR}/corridor_depthConfig.cmake
  INSTALL_DESTINATION lib/cmake/corridor_depth)
write_basic_package_version_file(
  ${PROJECT_BINARY_DIR}/corridor_depthConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMajorVersion)
install(FILES
  ${PROJECT_BINARY_DIR}/corridor_depthConfig.cmake
  ${PROJECT_BINARY_DIR}/corridor_depthConfigVersion.cmake
  DESTINATION lib/cmake/corridor_depth)
