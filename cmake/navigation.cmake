# navigation/: SocialMPC (costs, solvers, goal finder, control loop), social_mpc_node and the
# nav_benchmark tool.
add_library(ari_navigation
  src/navigation/agent_clearance_cost.cpp
  src/navigation/control_cost.cpp
  src/navigation/episode_scorer.cpp
  src/navigation/footprint_model.cpp
  src/navigation/geodesic_field.cpp
  src/navigation/goal_cost.cpp
  src/navigation/goal_finder.cpp
  src/navigation/goal_request.cpp
  src/navigation/grid_field.cpp
  src/navigation/group_space_cost.cpp
  src/navigation/heading_cost.cpp
  src/navigation/initial_guess.cpp
  src/navigation/mpc_solver.cpp
  src/navigation/mppi_solver.cpp
  src/navigation/navigation_config.cpp
  src/navigation/navigation_session.cpp
  src/navigation/navigator.cpp
  src/navigation/nlopt_solver.cpp
  src/navigation/obstacle_cost.cpp
  src/navigation/perceived_scene.cpp
  src/navigation/mlp_policy.cpp
  src/navigation/perception_report.cpp
  src/navigation/policy_controller.cpp
  src/navigation/policy_observation.cpp
  src/navigation/scene_tracker.cpp
  src/navigation/personal_space_cost.cpp
  src/navigation/signed_distance_field.cpp
  src/navigation/social_cost_map.cpp
  src/navigation/social_mpc.cpp
  src/navigation/social_spaces.cpp
  src/navigation/trajectory_cost.cpp
  src/navigation/unicycle_model.cpp
  src/navigation/view_cost.cpp)
target_link_libraries(ari_navigation PUBLIC ari_model PRIVATE opencv_core opencv_imgproc NLopt::nlopt)
target_include_directories(ari_navigation SYSTEM PRIVATE ${OpenCV_INCLUDE_DIRS})
# The navigation core runs on the real robot too: it must not depend on the 2D simulator.
ari_forbid_link(ari_navigation "box2d|ari_world")

if(CATKIN_ENABLE_TESTING)
  ari_add_gtest(test_navigation
    SOURCES
      test/navigation/test_cost_terms.cpp
      test/navigation/test_goal_finder.cpp
      test/navigation/test_goal_request.cpp
      test/navigation/test_navigation_config.cpp
      test/navigation/test_navigation_session.cpp
      test/navigation/test_navigator.cpp
      test/navigation/test_perception_report.cpp
      test/navigation/test_policy_controller.cpp
      test/navigation/test_scene_tracker.cpp
      test/navigation/test_episode_scorer.cpp
    LIBRARIES ari_navigation ari_world)
  target_include_directories(test_navigation PRIVATE test/world)
  target_compile_definitions(test_navigation PRIVATE ARI_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
endif()

# nav_benchmark: the navigation benchmark (a user-facing tool, `rosrun ari_social_sim nav_benchmark`).
add_executable(nav_benchmark src/tools/nav_benchmark/nav_benchmark.cpp
  src/tools/nav_benchmark/episode_record.cpp)
target_link_libraries(nav_benchmark ari_learning ari_batch)
target_compile_definitions(nav_benchmark PRIVATE ARI_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
install(TARGETS nav_benchmark RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
if(CATKIN_ENABLE_TESTING)
  ari_add_gtest(test_nav_benchmark SOURCES test/tools/test_nav_benchmark.cpp)
  target_compile_definitions(test_nav_benchmark PRIVATE
    ARI_NAV_BENCHMARK_BIN="$<TARGET_FILE:nav_benchmark>")
  add_dependencies(test_nav_benchmark nav_benchmark)
endif()

# social_mpc_node: thin ROS adapter over the navigation core.
add_library(ari_navigation_conversions
  src/navigation_conversions/measured_ari.cpp
  src/navigation_conversions/navigation_msgs.cpp)
target_link_libraries(ari_navigation_conversions PUBLIC ari_navigation ari_world_conversions)
add_executable(social_mpc_node src/nodes/social_mpc_node.cpp)
target_link_libraries(social_mpc_node ari_navigation_conversions ari_perception_conversions)

if(CATKIN_ENABLE_TESTING)
  add_rostest_gtest(test_social_navigation test/integration/social_navigation.test
    test/integration/test_social_navigation.cpp)
  target_include_directories(test_social_navigation PRIVATE ${CATKIN_DEVEL_PREFIX}/include ${catkin_INCLUDE_DIRS})
  target_link_libraries(test_social_navigation ari_perception ${catkin_LIBRARIES})
  add_dependencies(test_social_navigation ${PROJECT_NAME}_generate_messages_cpp social_mpc_node world_node
    hri_perception_node group_detection_node)
  add_rostest(test/integration/hostile_inputs.test DEPENDENCIES world_node hri_perception_node
    social_mpc_node)
endif()

if(benchmark_FOUND)
  ari_add_benchmark(bench_navigation
    SOURCES bench/bench_navigation.cpp
    LIBRARIES ari_navigation ari_world)
  # The scenes are the navigation tests' own (test/navigation/navigation_fixtures.hpp).
  target_include_directories(bench_navigation PRIVATE ${PROJECT_SOURCE_DIR}/test/navigation
    ${PROJECT_SOURCE_DIR}/test/world)
  target_compile_definitions(bench_navigation PRIVATE ARI_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
endif()
