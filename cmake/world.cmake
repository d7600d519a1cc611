# world/: the 2D multi-party world on Box2D (D6.4 §3), and world_node.
add_library(ari_world
  src/world/agent_grid.cpp
  src/world/ari.cpp
  src/world/box2d_shapes.cpp
  src/world/conversation_gaze.cpp
  src/world/conversation_metrics.cpp
  src/world/differential_drive.cpp
  src/world/formation_layout.cpp
  src/world/gaze_generator.cpp
  src/world/group_conversation.cpp
  src/world/head_nod.cpp
  src/world/group_turnover.cpp
  src/world/group_navigation.cpp
  src/world/group_report.cpp
  src/world/head_pan_controller.cpp
  src/world/human.cpp
  src/world/human_navigation.cpp
  src/world/member_manner.cpp
  src/world/map_sensor.cpp
  src/world/object.cpp
  src/world/posture.cpp
  src/world/request_check.cpp
  src/world/robot_reaction.cpp
  src/world/scene.cpp
  src/world/service_requests.cpp
  src/world/simulation.cpp
  src/world/social_forces.cpp
  src/world/speech_generator.cpp
  src/world/walking_group.cpp
  src/world/walking_route.cpp
  src/world/world_run_config.cpp
  src/world/world_snapshot.cpp)
target_link_libraries(ari_world PUBLIC ari_model box2d::box2d)

if(CATKIN_ENABLE_TESTING)
  ari_add_gtest(test_world
    SOURCES
      test/world/test_agent_grid.cpp
      test/world/test_crowd_scene.cpp
      test/world/test_gaze_generator.cpp
      test/world/test_group_arrangements.cpp
      test/world/test_group_navigation.cpp
      test/world/test_group_turnover.cpp
      test/world/test_map_sensor.cpp
      test/world/test_posture.cpp
      test/world/test_request_check.cpp
      test/world/test_robot_reaction.cpp
      test/world/test_scene.cpp
      test/world/test_simulation.cpp
      test/world/test_social_forces.cpp
      test/world/test_speech_generator.cpp
      test/world/test_walking_group.cpp
      test/world/test_world_requests.cpp
      test/world/test_world_run_config.cpp
    LIBRARIES ari_world)
  target_compile_definitions(test_world PRIVATE ARI_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
endif()

# What every node shares (node_support/): parameters, input counters, a renewing tf buffer, one
# publisher per topic, image messages, the frames' names and the common main. Its headers, like
# those of every ROS-side library, are included by folder ("node_support/frames.hpp").
find_package(OpenCV REQUIRED COMPONENTS core imgproc imgcodecs)
add_library(ari_node_support
  src/node_support/image.cpp
  src/node_support/input_counters.cpp
  src/node_support/renewing_tf_buffer.cpp
  src/node_support/ros_params.cpp
  src/node_support/single_publisher.cpp)
target_include_directories(ari_node_support PUBLIC ${PROJECT_SOURCE_DIR}/src
  ${CATKIN_DEVEL_PREFIX}/include ${catkin_INCLUDE_DIRS} ${OpenCV_INCLUDE_DIRS})
target_link_libraries(ari_node_support PUBLIC ari_core ${catkin_LIBRARIES} opencv_core opencv_imgproc
  opencv_imgcodecs)
add_dependencies(ari_node_support ${PROJECT_NAME}_generate_messages_cpp)

# world_node: thin ROS adapter over the world core.
add_library(ari_world_conversions
  src/world_conversions/ari_base.cpp
  src/world_conversions/marker_builder.cpp
  src/world_conversions/world_markers.cpp
  src/world_conversions/transform.cpp
  src/world_conversions/world_state.cpp)
target_link_libraries(ari_world_conversions PUBLIC ari_world ari_node_support)

add_executable(world_node src/nodes/world_node.cpp)
target_link_libraries(world_node ari_world_conversions ari_world_speech)

if(benchmark_FOUND)
  ari_add_benchmark(bench_world
    SOURCES bench/bench_world.cpp
    LIBRARIES ari_world_speech)
  target_compile_definitions(bench_world PRIVATE ARI_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  # The scenes are the world tests' own (test/world/scene_builders.hpp).
  target_include_directories(bench_world PRIVATE ${PROJECT_SOURCE_DIR}/test/world)
endif()

if(CATKIN_ENABLE_TESTING)
  add_rostest(test/integration/world_node.test DEPENDENCIES world_node)
  add_rostest(test/integration/world_node_sigint.test DEPENDENCIES world_node)
  add_rostest(test/integration/world_node_3d_inputs.test DEPENDENCIES world_node)
  ari_add_gtest(test_world_state_determinism
    SOURCES test/nodes/test_world_state_determinism.cpp
    LIBRARIES ari_world_conversions)
  target_compile_definitions(test_world_state_determinism PRIVATE ARI_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  ari_add_gtest(test_world_state_conversion
    SOURCES test/nodes/test_world_state_conversion.cpp
    LIBRARIES ari_world_conversions)
  target_compile_definitions(test_world_state_conversion PRIVATE ARI_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
endif()
