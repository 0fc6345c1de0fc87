# The live ROS 1 node (ros/): Debian's roscpp, image_transport, tf2_ros and the message headers.
# As for the bags (CorridorDependencies.cmake), their catkin configs need a catkin workspace, so the
# headers and libraries are found by hand and wrapped in one imported target, corridor::ros1_node.
# Sets CORRIDOR_ROS_NODE_FOUND; the option CORRIDOR_WITH_ROS (top CMakeLists.txt) defaults to it.
set(CORRIDOR_ROS_NODE_FOUND OFF)
set(CORRIDOR_ROS_NODE_MISSING "")
if(TARGET corridor::ros1)
  set(corridor_node_headers ros/ros.h image_transport/image_transport.h
      visualization_msgs/MarkerArray.h diagnostic_msgs/DiagnosticArray.h tf2_ros/buffer.h
      std_msgs/Header.h geometry_msgs/TransformStamped.h)
  set(corridor_node_include_dirs "")
  foreach(header ${corridor_node_headers})
    string(MAKE_C_IDENTIFIER "CORRIDOR_NODE_INC_${header}" var)
    find_path(${var} ${header})
    if(${var})
      list(APPEND corridor_node_include_dirs ${${var}})
    else()
      list(APPEND CORRIDOR_ROS_NODE_MISSING ${header})
    endif()
  endforeach()
  set(corridor_node_link "")
  foreach(lib roscpp rosconsole roscpp_serialization rostime cpp_common xmlrpcpp image_transport
              tf2_ros tf2)
    find_library(CORRIDOR_NODE_LIB_${lib} ${lib})
    if(CORRIDOR_NODE_LIB_${lib})
      list(APPEND corridor_node_link ${CORRIDOR_NODE_LIB_${lib}})
    else()
      list(APPEND CORRIDOR_ROS_NODE_MISSING lib${lib})
    endif()
  endforeach()
  if(NOT CORRIDOR_ROS_NODE_MISSING)
    set(CORRIDOR_ROS_NODE_FOUND ON)
    if(NOT TARGET corridor::ros1_node)
      list(REMOVE_DUPLICATES corridor_node_include_dirs)
      add_library(corridor::ros1_node INTERFACE IMPORTED)
      set_target_properties(corridor::ros1_node PROPERTIES
        INTERFACE_INCLUDE_DIRECTORIES "${corridor_node_include_dirs}"
        INTERFACE_LINK_LIBRARIES "corridor::ros1;${corridor_node_link};Threads::Threads")
    endif()
  endif()
else()
  set(CORRIDOR_ROS_NODE_MISSING "ROS 1 bag support (CORRIDOR_WITH_ROSBAG)")
endif()
