# perception/: what ARI perceives of the people around it (ROS4HRI bodies, faces, voices, persons,
# with error models), GCFF F-formation groups and their evaluation; the detect_groups tool,
# hri_perception_node and group_detection_node.
add_library(ari_perception
  src/perception/ari_sensors.cpp
  src/perception/asr_errors.cpp
  src/perception/body_tracker.cpp
  src/perception/candidate_matches.cpp
  src/perception/detection_model.cpp
  src/perception/engagement.cpp
  src/perception/expression.cpp
  src/perception/face_tracker.cpp
  src/perception/fformation_dataset.cpp
  src/perception/fformation_geometry.cpp
  src/perception/field_of_view.cpp
  src/perception/gcff.cpp
  src/perception/grid_raycast.cpp
  src/perception/group_candidates.cpp
  src/perception/group_detection_run_config.cpp
  src/perception/group_evaluation.cpp
  src/perception/group_perception.cpp
  src/perception/group_tracker.cpp
  src/perception/image_regions.cpp
  src/perception/membership_filter.cpp
  src/perception/perception_config.cpp
  src/perception/perception_pipeline.cpp
  src/perception/perception_run_config.cpp
  src/perception/person_registry.cpp
  src/perception/pose_noise.cpp
  src/perception/rate_gate.cpp
  src/perception/sound_map.cpp
  src/perception/speech_listener.cpp
  src/perception/track_ids.cpp
  src/perception/tracked_persons.cpp
  src/perception/transient_ids.cpp
  src/perception/visibility.cpp)
target_include_directories(ari_perception PUBLIC include)
# The world's plain types (snapshots, occupancy grid) are the perception's input.
target_link_libraries(ari_perception PUBLIC ari_core ari_world)

# Lands in devel/lib/ari_social_sim, so `rosrun ari_social_sim detect_groups` finds it.
add_executable(detect_groups src/tools/detect_groups.cpp)
target_link_libraries(detect_groups ari_perception)
install(TARGETS detect_groups RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})

# hri_perception_node and group_detection_node: thin ROS adapters over the perception core
# (ROS4HRI topics, tf, markers).
# With PerceivedPersons: what the nodes that act on perceived people (social_mpc_node,
# scenario_node, group_detection_node) read of ROS4HRI.
add_library(ari_perception_conversions
  src/perception_conversions/group_markers.cpp
  src/perception_conversions/hri_messages.cpp
  src/perception_conversions/heard_speech.cpp
  src/perception_conversions/perceived_persons.cpp
  src/perception_conversions/perception_markers.cpp)
target_link_libraries(ari_perception_conversions PUBLIC ari_perception ari_world_conversions)

add_executable(hri_perception_node src/nodes/hri_perception_node.cpp)
target_link_libraries(hri_perception_node ari_perception_conversions ari_rendering)
install(TARGETS hri_perception_node RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})

# group_detection_node: GCFF on whichever persons /humans/persons/tracked lists, placed from tf.
add_executable(group_detection_node src/nodes/group_detection_node.cpp)
target_link_libraries(group_detection_node ari_perception_conversions)
install(TARGETS group_detection_node RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})

if(CATKIN_ENABLE_TESTING)
  # The tests that read the F-formation data sets (docs/data.md) find them at run time in
  # $ARI_DATA_DIR/fformation and are skipped, with the reason, without them.
  ari_add_gtest(test_perception
    SOURCES
      test/perception/test_ari_sensors.cpp
      test/perception/test_asr_errors.cpp
      test/perception/test_body_tracker.cpp
      test/perception/test_candidate_matches.cpp
      test/perception/test_detection_model.cpp
      test/perception/test_engagement.cpp
      test/perception/test_face_tracker.cpp
      test/perception/test_fformation_dataset.cpp
      test/perception/test_fformation_geometry.cpp
      test/perception/test_field_of_view.cpp
      test/perception/test_gcff.cpp
      test/perception/test_gcff_reference.cpp
      test/perception/test_grid_raycast.cpp
      test/perception/test_group_candidates.cpp
      test/perception/test_group_detection_run_config.cpp
      test/perception/test_group_evaluation.cpp
      test/perception/test_group_perception.cpp
      test/perception/test_membership_filter.cpp
      test/perception/test_group_tracker.cpp
      test/perception/test_image_regions.cpp
      test/perception/test_perception_config.cpp
      test/perception/test_perception_pipeline.cpp
      test/perception/test_per_id_store.cpp
      test/perception/test_perception_run_config.cpp
      test/perception/test_person_registry.cpp
      test/perception/test_pose_noise.cpp
      test/perception/test_rate_gate.cpp
      test/perception/test_sound_map.cpp
      test/perception/test_speech_listener.cpp
      test/perception/test_track_ids.cpp
      test/perception/test_transient_ids.cpp
      test/perception/test_visibility.cpp
      test/perception/test_world_formations.cpp
    LIBRARIES ari_perception)
  target_compile_definitions(test_perception PRIVATE
    ARI_SOURCE_DIR="${PROJECT_SOURCE_DIR}")

  ari_add_gtest(test_perception_conversions
    SOURCES test/perception_conversions/test_hri_transforms.cpp
    LIBRARIES ari_perception_conversions)

  add_rostest(test/integration/hri_wire.test DEPENDENCIES world_node hri_perception_node)
  add_rostest(test/integration/hri_perception.test DEPENDENCIES world_node hri_perception_node)
  add_rostest(test/integration/launch_arguments.test)
  add_rostest(test/integration/group_detection.test
    DEPENDENCIES world_node hri_perception_node group_detection_node)
  add_rostest(test/integration/group_detection_alone.test DEPENDENCIES group_detection_node)
  add_rostest(test/integration/group_detection_synthetic.test DEPENDENCIES group_detection_node)
  # Clients of the /humans/... topics as ROS4HRI's own behave: a pyhri 0.4.1-like listener on
  # the sim perception, and a stand-in for hri_person_manager on the detectors-only perception.
  add_rostest(test/integration/pyhri_client.test DEPENDENCIES world_node hri_perception_node)
  add_rostest(test/integration/person_manager_standin.test
    DEPENDENCIES world_node hri_perception_node)

  ari_add_gtest(test_detect_groups SOURCES test/tools/test_detect_groups.cpp LIBRARIES ari_core)
  target_compile_definitions(test_detect_groups PRIVATE
    ARI_DETECT_GROUPS_BIN="$<TARGET_FILE:detect_groups>")
  add_dependencies(test_detect_groups detect_groups)
endif()

if(benchmark_FOUND)
  ari_add_benchmark(bench_perception
    SOURCES bench/bench_perception.cpp
    LIBRARIES ari_perception)
  # The scenes are the perception tests' own (test/perception/perception_scenes.hpp).
  target_include_directories(bench_perception PRIVATE ${PROJECT_SOURCE_DIR}/test/perception)

  # perception_soak: hours of sim time of the perception stack on a crowd, printing the size of
  # every per-id container (docs/PERFORMANCE.md, "Soak"). A plain program (it prints a table over
  # time rather than timing a case), built with the benchmarks.
  add_executable(perception_soak EXCLUDE_FROM_ALL bench/perception_soak.cpp)
  target_link_libraries(perception_soak ari_perception ari_navigation ari_engine ari_world)
  target_include_directories(perception_soak PRIVATE ${PROJECT_SOURCE_DIR}/test/world)
  set_target_properties(perception_soak PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/bench)
  add_dependencies(benchmarks perception_soak)
endif()
