# corridor_score: recovered junctions of labelled photos against their hand labels.
corridor_add_executable(corridor_score
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/corridor_score_main.cc ${CMAKE_CURRENT_LIST_DIR}/label_sheet.cc
          ${CMAKE_CURRENT_LIST_DIR}/label_sheet.h
  DEPS corridor_tool_support corridor_evaluation glog::glog opencv_imgproc)
