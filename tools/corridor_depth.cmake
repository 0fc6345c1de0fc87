corridor_add_library(corridor_tool_support
  SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/focal_auto.cc ${CMAKE_CURRENT_LIST_DIR}/frame_source.cc
    ${CMAKE_CURRENT_LIST_DIR}/geometry_csv.cc
    ${CMAKE_CURRENT_LIST_DIR}/input_source.cc ${CMAKE_CURRENT_LIST_DIR}/tool_flags.cc
  HEADERS
    ${CMAKE_CURRENT_LIST_DIR}/focal_auto.h ${CMAKE_CURRENT_LIST_DIR}/frame_source.h
    ${CMAKE_CURRENT_LIST_DIR}/geometry_csv.h
    ${CMAKE_CURRENT_LIST_DIR}/input_source.h ${CMAKE_CURRENT_LIST_DIR}/tool_flags.h
  DEPS corridor_tool_help corridor_evaluation corridor_pipeline corridor_io corridor_depth_planes
       gflags::gflags opencv_videoio)
# Bag input and --output_bag when ROS 1 support is built.
if(CORRIDOR_WITH_ROSBAG)
  target_link_libraries(corridor_tool_support PUBLIC corridor_rosbag)
endif()
corridor_add_executable(corridor_depth
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/corridor_depth_main.cc
  DEPS corridor_tool_support glog::glog)
