# Finds every third-party package the project uses. All come from Debian (scripts/install_deps.sh).
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(OpenCV REQUIRED COMPONENTS core imgproc imgcodecs highgui videoio calib3d)
find_package(Ceres REQUIRED)
find_package(glog REQUIRED)
find_package(gflags REQUIRED)
find_package(yaml-cpp REQUIRED)
find_package(Threads REQUIRED)

# Debian's gflags exports `gflags`, not `gflags::gflags`.
if(NOT TARGET gflags::gflags)
  add_library(gflags::gflags INTERFACE IMPORTED)
  set_target_properties(gflags::gflags PROPERTIES INTERFACE_LINK_LIBRARIES gflags)
endif()
# yaml-cpp 0.7 exports the plain `yaml-cpp` target.
if(NOT TARGET yaml-cpp::yaml-cpp)
  add_library(yaml-cpp::yaml-cpp INTERFACE IMPORTED)
  set_target_properties(yaml-cpp::yaml-cpp PROPERTIES INTERFACE_LINK_LIBRARIES yaml-cpp)
endif()

if(CORRIDOR_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()
if(CORRIDOR_BUILD_BENCHMARKS)
  find_package(benchmark REQUIRED)
endif()
