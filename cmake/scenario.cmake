# scenario/: scenario files (a scene plus a script), the state machine that plays them, and
# scenario_node, which plays them through the suite's public services and actions.

# scenario::WorldSpeechStage, the world stage of dialogue_node and of the engine: a library of its
# own so that dialogue_node links neither perception nor navigation.
add_library(ari_world_speech_stage src/scenario/world_speech_stage.cpp)
target_link_libraries(ari_world_speech_stage PUBLIC ari_dialogue ari_world)

add_library(ari_scenario
  src/scenario/agent_ref.cpp
  src/scenario/ari_observation.cpp
  src/scenario/batch_plan.cpp
  src/scenario/conversation.cpp
  src/scenario/episode.cpp
  src/scenario/episode_csv.cpp
  src/scenario/episode_metrics.cpp
  src/scenario/in_process_navigation.cpp
  src/scenario/episode_report.cpp
  src/scenario/group_memory.cpp
  src/scenario/group_streams.cpp
  src/scenario/progress_bar.cpp
  src/scenario/observations.cpp
  src/scenario/person_identities.cpp
  src/scenario/random_group.cpp
  src/scenario/random_group_scene.cpp
  src/scenario/scenario.cpp
  src/scenario/run_watchdog.cpp
  src/scenario/scenario_run_config.cpp
  src/scenario/script.cpp
  src/scenario/script_runner.cpp
  src/scenario/transcript.cpp)
target_link_libraries(ari_scenario
  PUBLIC ari_world ari_perception ari_dialogue ari_navigation ari_world_speech_stage)

add_library(ari_scenario_conversions src/nodes/conversions/scenario_status.cpp)
target_link_libraries(ari_scenario_conversions PUBLIC ari_scenario ari_world_conversions)
target_include_directories(ari_scenario_conversions PUBLIC ${CATKIN_DEVEL_PREFIX}/include)
add_executable(scenario_node src/nodes/scenario_node.cpp)
target_link_libraries(scenario_node ari_scenario_conversions ari_dialogue_conversions
  ari_navigation_conversions ari_perceived_persons)

# run_episodes: the batch tool (cores in one process, rosbags written without a master).
add_library(ari_episode_bag src/tools/episode_bag.cpp)
target_link_libraries(ari_episode_bag
  PUBLIC ari_scenario_conversions ari_perception_conversions ari_dialogue_conversions
    ari_navigation_conversions)
add_executable(run_episodes src/tools/run_episodes.cpp)
target_link_libraries(run_episodes ari_episode_bag)
target_compile_definitions(run_episodes PRIVATE
  ARI_SCENARIO_DIR="${CMAKE_CURRENT_SOURCE_DIR}/scenarios"
  ARI_CONFIG_DIR="${CMAKE_CURRENT_SOURCE_DIR}/config")

# export_dataset: labelled images of ARI's cameras from a scenario's episodes as a COCO dataset,
# the engine and the renderer in one process (docs/cameras.md, "Labelled datasets").
add_library(ari_dataset src/scenario/coco_dataset.cpp)
target_link_libraries(ari_dataset PUBLIC ari_scenario ari_rendering)
add_executable(export_dataset src/tools/export_dataset.cpp)
target_link_libraries(export_dataset ari_dataset)
target_compile_definitions(export_dataset PRIVATE
  ARI_SCENARIO_DIR="${CMAKE_CURRENT_SOURCE_DIR}/scenarios"
  ARI_CONFIG_DIR="${CMAKE_CURRENT_SOURCE_DIR}/config")
if(CATKIN_ENABLE_TESTING)
  # The COCO file's layout, and the program itself run as a user would.
  ari_add_gtest(test_export_dataset
    SOURCES test/scenario/test_coco_dataset.cpp test/tools/test_export_dataset.cpp
    LIBRARIES ari_dataset)
  target_compile_definitions(test_export_dataset PRIVATE
    ARI_EXPORT_DATASET_BIN="$<TARGET_FILE:export_dataset>")
  add_dependencies(test_export_dataset export_dataset)
endif()

# export_group_streams: what perception reports of random group scenes, as the CSV files of an
# F-formation data set for detect_groups (docs/perception_gcff.md, "GCFF on perceived streams").
add_executable(export_group_streams src/tools/export_group_streams.cpp)
target_link_libraries(export_group_streams ari_scenario)
target_compile_definitions(export_group_streams PRIVATE
  ARI_WORLD_DIR="${CMAKE_CURRENT_SOURCE_DIR}/worlds"
  ARI_CONFIG_DIR="${CMAKE_CURRENT_SOURCE_DIR}/config")
if(CATKIN_ENABLE_TESTING)
  # The program run as a user would, its files read with detect_groups' readers and scored.
  ari_add_gtest(test_export_group_streams
    SOURCES test/tools/test_export_group_streams.cpp
    LIBRARIES ari_perception)
  target_compile_definitions(test_export_group_streams PRIVATE
    ARI_EXPORT_GROUP_STREAMS_BIN="$<TARGET_FILE:export_group_streams>")
  add_dependencies(test_export_group_streams export_group_streams)
endif()

if(CATKIN_ENABLE_TESTING)
  ari_add_gtest(test_scenario
    SOURCES
      test/scenario/test_agent_ref.cpp
      test/scenario/test_batch_plan.cpp
      test/scenario/test_conversation.cpp
      test/scenario/test_episode_csv.cpp
      test/scenario/test_episode_metrics.cpp
      test/scenario/test_episode_report.cpp
      test/scenario/test_episode_config.cpp
      test/scenario/test_episode_requests.cpp
      test/scenario/test_observations.cpp
      test/scenario/test_group_memory.cpp
      test/scenario/test_group_streams.cpp
      test/scenario/test_person_identities.cpp
      test/scenario/test_progress_bar.cpp
      test/scenario/test_random_group.cpp
      test/scenario/test_random_group_scene.cpp
      test/scenario/test_scenario.cpp
      test/scenario/test_run_watchdog.cpp
      test/scenario/test_scenario_run_config.cpp
      test/scenario/test_script_runner.cpp
      test/scenario/test_transcript.cpp
    LIBRARIES ari_scenario)
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

if(CATKIN_ENABLE_TESTING)
  # Issue 14: the engine and the nodes' cores composed as the nodes compose them, step by step.
  ari_add_gtest(test_live_batch_equivalence
    SOURCES test/nodes/test_live_batch_equivalence.cpp
    LIBRARIES ari_episode_bag ari_perceived_persons ari_navigation_conversions)
  target_compile_definitions(test_live_batch_equivalence PRIVATE
    ARI_SOURCE_DIR="${PROJECT_SOURCE_DIR}")

  ari_add_gtest(test_episode_bag
    SOURCES test/tools/test_episode_bag.cpp
    LIBRARIES ari_episode_bag)
  target_compile_definitions(test_episode_bag PRIVATE ARI_SOURCE_DIR="${PROJECT_SOURCE_DIR}")

  # The program itself, run as a user would (test/tools/program_run.hpp).
  ari_add_gtest(test_run_episodes
    SOURCES test/tools/test_run_episodes.cpp
    LIBRARIES ${catkin_LIBRARIES})
  target_include_directories(test_run_episodes PRIVATE ${catkin_INCLUDE_DIRS})
  target_compile_definitions(test_run_episodes PRIVATE
    ARI_RUN_EPISODES_BIN="$<TARGET_FILE:run_episodes>" ARI_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  add_dependencies(test_run_episodes run_episodes)
endif()

if(benchmark_FOUND)
  ari_add_benchmark(bench_scenario SOURCES bench/bench_scenario.cpp LIBRARIES ari_episode_bag)
  target_compile_definitions(bench_scenario PRIVATE ARI_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  target_include_directories(bench_scenario PRIVATE ${PROJECT_SOURCE_DIR}/src/tools)
endif()

if(CATKIN_ENABLE_TESTING)
  # The signal fuzz (issue 28): every batch tool, of every module, stopped by SIGINT or SIGTERM at
  # a seeded random moment; here, where the last of them is defined.
  ari_add_gtest(test_tool_signals SOURCES test/tools/test_tool_signals.cpp)
  target_compile_definitions(test_tool_signals PRIVATE
    ARI_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
    ARI_RUN_EPISODES_BIN="$<TARGET_FILE:run_episodes>"
    ARI_EXPORT_DATASET_BIN="$<TARGET_FILE:export_dataset>"
    ARI_NAV_BENCHMARK_BIN="$<TARGET_FILE:nav_benchmark>"
    ARI_RENDER_CAMERAS_BIN="$<TARGET_FILE:render_cameras>"
    ARI_DETECT_GROUPS_BIN="$<TARGET_FILE:detect_groups>"
    ARI_DIALOGUE_CORPUS_BIN="$<TARGET_FILE:dialogue_corpus>"
    ARI_EXPORT_GROUP_STREAMS_BIN="$<TARGET_FILE:export_group_streams>"
    ARI_FIT_DIALOGUE_MODEL_BIN="$<TARGET_FILE:fit_dialogue_model>")
  add_dependencies(test_tool_signals run_episodes export_dataset nav_benchmark render_cameras
    detect_groups dialogue_corpus export_group_streams fit_dialogue_model)
endif()
