# Install rules and an exported CMake package: research code writes
#   find_package(corridor_depth REQUIRED)
#   target_link_libraries(app PRIVATE corridor_depth::corridor_depth)
include(CMakePackageConfigHelpers)

# The umbrella target; exported as corridor_depth::corridor_depth (the name `corridor_depth`
# itself belongs to the command-line tool).
add_library(corridor_depth_all INTERFACE)
target_link_libraries(corridor_depth_all INTERFACE ${CORRIDOR_LIBRARIES})
set_target_properties(corridor_depth_all PROPERTIES EXPORT_NAME corridor_depth)
add_library(corridor_depth::corridor_depth ALIAS corridor_depth_all)

install(TARGETS ${CORRIDOR_LIBRARIES} corridor_depth_all
  EXPORT corridor_depthTargets
  ARCHIVE DESTINATION lib
  LIBRARY DESTINATION lib
  RUNTIME DESTINATION bin
  INCLUDES DESTINATION include/corridor_depth)
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
  ${PROJECT_SOURCE_DIR}/cmake/CorridorDependencies.cmake
  DESTINATION lib/cmake/corridor_depth)
