# solver_compare: every solver on the same junction points (noise sweeps and dataset runs).
corridor_add_library(corridor_compare_support
  SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/compare/compare_report.cc
    ${CMAKE_CURRENT_LIST_DIR}/compare/solver_stats.cc
    ${CMAKE_CURRENT_LIST_DIR}/compare/synthetic_junctions.cc
    ${CMAKE_CURRENT_LIST_DIR}/compare/compare_report.h
    ${CMAKE_CURRENT_LIST_DIR}/compare/solver_stats.h
    ${CMAKE_CURRENT_LIST_DIR}/compare/synthetic_junctions.h
  DEPS corridor_eval_writers corridor_tool_support corridor_estimation)
corridor_add_executable(solver_compare
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/solver_compare_main.cc
  DEPS corridor_compare_support glog::glog)
