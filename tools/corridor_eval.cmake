# corridor_eval: batch evaluation against ground truth (the paper's Tables 1-4), with a report.
# The evaluation itself is the library's (evaluation/: EvaluateScenes, BuildReport,
# ReportTables); the tool adds its writers: report.md/json/csv, index.html and the plots.
set(CORRIDOR_EVAL_DIR ${CMAKE_CURRENT_LIST_DIR}/eval)
corridor_add_library(corridor_eval_writers
  SOURCES
    ${CORRIDOR_EVAL_DIR}/html_report.cc ${CORRIDOR_EVAL_DIR}/plot_canvas.cc
    ${CORRIDOR_EVAL_DIR}/plots.cc ${CORRIDOR_EVAL_DIR}/report_json.cc
    ${CORRIDOR_EVAL_DIR}/report_writers.cc
    # Headers of the tool's internals: listed as sources, so they are not installed.
    ${CORRIDOR_EVAL_DIR}/html_report.h ${CORRIDOR_EVAL_DIR}/plot_canvas.h
    ${CORRIDOR_EVAL_DIR}/plots.h ${CORRIDOR_EVAL_DIR}/report_writers.h
  DEPS corridor_tool_support corridor_evaluation corridor_io opencv_imgproc opencv_imgcodecs)
corridor_add_executable(corridor_eval
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/corridor_eval_main.cc
  DEPS corridor_eval_writers corridor_tool_support glog::glog)
