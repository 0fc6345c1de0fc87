corridor_add_executable(corridor_synth
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/corridor_synth_main.cc
  DEPS corridor_synthetic corridor_tool_help gflags::gflags glog::glog)
