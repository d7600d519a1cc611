# scenario/: scenario files (a scene plus a script), the state machine that plays them, and what a
# live run and an in-process run share (metrics, reports, group memory, the watchdog); and
# scenario_node, which plays them through the suite's public services and actions.
add_library(ari_scenario
  src/scenario/agent_ref.cpp
  src/scenario/conversation.cpp
  src/scenario/episode_metrics.cpp
  src/scenario/episode_report.cpp
  src/scenario/group_memory.cpp
  src/scenario/heard_lines.cpp
  src/scenario/observations.cpp
  src/scenario/person_identities.cpp
  src/scenario/random_group.cpp
  src/scenario/group_mix.cpp
  src/scenario/random_group_scene.cpp
  src/scenario/recognised_speech.cpp
  src/scenario/run_watchdog.cpp
  src/scenario/scenario.cpp
  src/scenario/scenario_run_config.cpp
  src/scenario/script.cpp
  src/scenario/script_runner.cpp
  src/scenario/transcript.cpp)
target_link_libraries(ari_scenario PUBLIC ari_world ari_perception ari_dialogue)

add_library(ari_scenario_conversions src/scenario_conversions/scenario_status.cpp)
target_link_libraries(ari_scenario_conversions PUBLIC ari_scenario ari_world_conversions)
add_executable(scenario_node src/nodes/scenario_node.cpp)
target_link_libraries(scenario_node ari_scenario_conversions ari_dialogue_conversions
  ari_navigation_conversions ari_perception_conversions)

if(CATKIN_ENABLE_TESTING)
  ari_add_gtest(test_scenario
    SOURCES
      test/scenario/test_agent_ref.cpp
      test/scenario/test_conversation.cpp
      test/scenario/test_episode_metrics.cpp
      test/scenario/test_episode_report.cpp
      test/scenario/test_observations.cpp
      test/scenario/test_group_memory.cpp
      test/scenario/test_person_identities.cpp
      test/scenario/test_random_group.cpp
      test/scenario/test_random_group_scene.cpp
      test/scenario/test_recognised_speech.cpp
      test/scenario/test_scenario.cpp
      test/scenario/test_run_watchdog.cpp
      test/scenario/test_scenario_run_config.cpp
      test/scenario/test_script_runner.cpp
      test/scenario/test_transcript.cpp
    LIBRARIES ari_scenario ari_batch)
  target_compile_definitions(test_scenario PRIVATE ARI_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  target_include_directories(test_scenario PRIVATE ${PROJECT_SOURCE_DIR}/test/world)

  add_rostest(test/integration/scenario_node.test DEPENDENCIES world_node scenario_node)
  # scenario_node never hangs and always reports: world_node killed mid-run, and SIGINT.
  add_rostest(test/integration/scenario_node_robustness.test
    DEPENDENCIES world_node scenario_node)
  # Hostile input to every node of the suite (issue 13).
  add_rostest(test/integration/fuzz.test DEPENDENCIES world_node hri_perception_node
    group_detection_node social_mpc_node dialogue_node)
  add_rostest(test/integration/scenario_suite.test DEPENDENCIES world_node hri_perception_node
    group_detection_node social_mpc_node dialogue_node scenario_node run_episodes)
  # scripts/run_launch.py (README, "Exit codes"): its mapping, then group_discussion through it
  # with a forced time limit (1), a node refusing its parameter (2), a bad launch argument (2).
  catkin_run_tests_target(pytest run_launch pytest-run_launch.xml
    COMMAND "${CMAKE_COMMAND} -E env PYTHONPATH=${CATKIN_DEVEL_PREFIX}/${CATKIN_GLOBAL_PYTHON_DESTINATION}:${PROJECT_SOURCE_DIR}/python /usr/bin/python3 -m pytest -q -p no:cacheprovider --junitxml=${CATKIN_TEST_RESULTS_DIR}/${PROJECT_NAME}/pytest-run_launch.xml ${PROJECT_SOURCE_DIR}/test/launch"
    DEPENDENCIES world_node hri_perception_node group_detection_node social_mpc_node
      dialogue_node scenario_node)
  # The same scenario with each kind of perception (README, "Swapping in real perception").
  foreach(perception_args "perception:=sim" "perception:=sim person_ids:=random"
                          "perception:=detectors")
    separate_arguments(perception_args)
    add_rostest(test/integration/scenario_perception_modes.test ARGS ${perception_args}
      DEPENDENCIES world_node hri_perception_node group_detection_node social_mpc_node
        dialogue_node scenario_node)
  endforeach()
endif()

