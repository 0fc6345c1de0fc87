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

# ROS 1 bags (bag input and --output_bag): Debian's rosbag_storage and sensor_msgs. Their catkin
# and ament CMake configs need a Python with ament_package, so the headers and libraries are found
# here by hand and wrapped in one imported target, corridor::ros1.
option(CORRIDOR_WITH_ROSBAG "Read and write ROS 1 bags (librosbag-storage-dev, libsensor-msgs-dev)"
       ON)
if(CORRIDOR_WITH_ROSBAG AND NOT TARGET corridor::ros1)
  find_path(CORRIDOR_ROSBAG_INCLUDE rosbag/bag.h)
  find_path(CORRIDOR_SENSOR_MSGS_INCLUDE sensor_msgs/Image.h)
  find_path(CORRIDOR_PLUGINLIB_INCLUDE pluginlib/class_loader.hpp PATH_SUFFIXES pluginlib)
  find_path(CORRIDOR_CLASS_LOADER_INCLUDE class_loader/class_loader.hpp PATH_SUFFIXES class_loader)
  find_path(CORRIDOR_RCUTILS_INCLUDE rcutils/types.h PATH_SUFFIXES rcutils)
  find_path(CORRIDOR_RCPPUTILS_INCLUDE rcpputils/filesystem_helper.hpp PATH_SUFFIXES rcpputils)
  find_path(CORRIDOR_AMENT_INDEX_INCLUDE ament_index_cpp/get_resource.hpp
            PATH_SUFFIXES ament_index_cpp)
  set(corridor_ros1_includes CORRIDOR_ROSBAG_INCLUDE CORRIDOR_SENSOR_MSGS_INCLUDE
      CORRIDOR_PLUGINLIB_INCLUDE CORRIDOR_CLASS_LOADER_INCLUDE CORRIDOR_RCUTILS_INCLUDE
      CORRIDOR_RCPPUTILS_INCLUDE CORRIDOR_AMENT_INDEX_INCLUDE)
  set(corridor_ros1_libs rosbag_storage rostime roscpp_serialization cpp_common console_bridge
      boost_filesystem)
  set(corridor_ros1_missing "")
  set(corridor_ros1_include_dirs "")
  foreach(var ${corridor_ros1_includes})
    if(${var})
      list(APPEND corridor_ros1_include_dirs ${${var}})
    else()
      list(APPEND corridor_ros1_missing ${var})
    endif()
  endforeach()
  set(corridor_ros1_link "")
  foreach(lib ${corridor_ros1_libs})
    find_library(CORRIDOR_LIB_${lib} ${lib})
    if(CORRIDOR_LIB_${lib})
      list(APPEND corridor_ros1_link ${CORRIDOR_LIB_${lib}})
    else()
      list(APPEND corridor_ros1_missing lib${lib})
    endif()
  endforeach()
  if(corridor_ros1_missing)
    message(FATAL_ERROR "ROS 1 bag support needs librosbag-storage-dev and libsensor-msgs-dev "
            "(run scripts/install_deps.sh as root), or configure with -DCORRIDOR_WITH_ROSBAG=OFF. "
            "Not found: ${corridor_ros1_missing}")
  endif()
  list(REMOVE_DUPLICATES corridor_ros1_include_dirs)
  add_library(corridor::ros1 INTERFACE IMPORTED)
  set_target_properties(corridor::ros1 PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${corridor_ros1_include_dirs}"
    INTERFACE_LINK_LIBRARIES "${corridor_ros1_link}")
endif()
