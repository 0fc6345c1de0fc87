corridor_add_library(corridor_tool_support
  SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/geometry_csv.cc ${CMAKE_CURRENT_LIST_DIR}/input_source.cc
    ${CMAKE_CURRENT_LIST_DIR}/progress.cc ${CMAKE_CURRENT_LIST_DIR}/tool_flags.cc
  HEADERS
    ${CMAKE_CURRENT_LIST_DIR}/geometry_csv.h ${CMAKE_CURRENT_LIST_DIR}/input_source.h
    ${CMAKE_CURRENT_LIST_DIR}/progress.h ${CMAKE_CURRENT_LIST_DIR}/tool_flags.h
  DEPS corridor_pipeline corridor_io gflags::gflags)
corridor_add_executable(corridor_depth
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/corridor_depth_main.cc
  DEPS corridor_tool_support glog::glog)
