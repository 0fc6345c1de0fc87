# corridor_eval: batch evaluation against ground truth (the paper's Tables 1-4), with a report.
set(CORRIDOR_EVAL_DIR ${CMAKE_CURRENT_LIST_DIR}/eval)
corridor_add_library(corridor_eval_support
  SOURCES
    ${CORRIDOR_EVAL_DIR}/eval_runner.cc ${CORRIDOR_EVAL_DIR}/frame_evaluator.cc
    ${CORRIDOR_EVAL_DIR}/frame_panel.cc ${CORRIDOR_EVAL_DIR}/html_report.cc
    ${CORRIDOR_EVAL_DIR}/plot_canvas.cc ${CORRIDOR_EVAL_DIR}/plots.cc
    ${CORRIDOR_EVAL_DIR}/report_builder.cc ${CORRIDOR_EVAL_DIR}/report_json.cc
    ${CORRIDOR_EVAL_DIR}/report_tables.cc ${CORRIDOR_EVAL_DIR}/report_writers.cc
    # Headers of the tool's internals: listed as sources, so they are not installed.
    ${CORRIDOR_EVAL_DIR}/eval_runner.h ${CORRIDOR_EVAL_DIR}/frame_evaluator.h
    ${CORRIDOR_EVAL_DIR}/frame_panel.h ${CORRIDOR_EVAL_DIR}/html_report.h
    ${CORRIDOR_EVAL_DIR}/plot_canvas.h ${CORRIDOR_EVAL_DIR}/plots.h
    ${CORRIDOR_EVAL_DIR}/report_builder.h ${CORRIDOR_EVAL_DIR}/report_tables.h
    ${CORRIDOR_EVAL_DIR}/report_writers.h
  DEPS corridor_tool_support corridor_evaluation corridor_pipeline corridor_io opencv_imgproc
       opencv_imgcodecs Threads::Threads)
corridor_add_executable(corridor_eval
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/corridor_eval_main.cc
  DEPS corridor_eval_support corridor_tool_support glog::glog)
