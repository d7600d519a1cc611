find_library(SNDFILE_LIBRARY sndfile REQUIRED)
# The batch libraries and tools: plans and outputs, rosbags of episodes, labelled image data sets.

# batch/: what the batch tools share: batch plans (episodes, seeds, shards, resuming), episode CSV
# files, progress lines, and the perceived group streams of random scenes.
add_library(ari_batch
  src/batch/batch_plan.cpp
  src/batch/corpus_shard_merge.cpp
  src/batch/episode_csv.cpp
  src/batch/group_streams.cpp
  src/batch/progress_bar.cpp
  src/batch/shard_merge.cpp)
target_link_libraries(ari_batch PUBLIC ari_engine)

if(CATKIN_ENABLE_TESTING)
  ari_add_gtest(test_batch
    SOURCES
      test/batch/test_batch_plan.cpp
      test/batch/test_episode_csv.cpp
      test/batch/test_group_streams.cpp
      test/batch/test_progress_bar.cpp
    LIBRARIES ari_batch)
  target_compile_definitions(test_batch PRIVATE ARI_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  target_include_directories(test_batch PRIVATE ${PROJECT_SOURCE_DIR}/test/world)
endif()

# episode_bag/: an episode as a rosbag, with the message types a live run records, written
# without a ROS master.
add_library(ari_episode_bag src/episode_bag/episode_bag.cpp)
target_link_libraries(ari_episode_bag
  PUBLIC ari_batch ari_scenario_conversions ari_perception_conversions ari_dialogue_conversions
    ari_navigation_conversions)

# run_episodes: the batch tool (cores in one process, rosbags written without a master).
add_executable(run_episodes src/tools/run_episodes.cpp)
target_link_libraries(run_episodes ari_episode_bag ari_dataset)
target_compile_definitions(run_episodes PRIVATE
  ARI_SCENARIO_DIR="${CMAKE_CURRENT_SOURCE_DIR}/scenarios"
  ARI_CONFIG_DIR="${CMAKE_CURRENT_SOURCE_DIR}/config")

# export_dataset: labelled images of ARI's cameras from a scenario's episodes as a COCO dataset,
# the engine and the renderer in one process (docs/cameras.md, "Labelled datasets").
# dataset/: the data sets: COCO of labelled camera images (and its shards' files merged), and an
# episode's audio (WAV, RTTM, CTM).
add_library(ari_dataset src/dataset/coco_dataset.cpp src/dataset/episode_audio.cpp
  src/dataset/shard_merge.cpp)
target_link_libraries(ari_dataset PUBLIC ari_batch ari_rendering ari_audio PRIVATE ${SNDFILE_LIBRARY})
add_executable(export_dataset src/tools/export_dataset.cpp)
target_link_libraries(export_dataset ari_dataset)
target_compile_definitions(export_dataset PRIVATE
  ARI_SCENARIO_DIR="${CMAKE_CURRENT_SOURCE_DIR}/scenarios"
  ARI_CONFIG_DIR="${CMAKE_CURRENT_SOURCE_DIR}/config")
if(CATKIN_ENABLE_TESTING)
  # The COCO file's layout, its shards' files merged, and the program itself run as a user would.
  ari_add_gtest(test_export_dataset
    SOURCES test/dataset/test_coco_dataset.cpp test/dataset/test_shard_merge.cpp
      test/tools/test_export_dataset.cpp
    LIBRARIES ari_dataset)
  target_compile_definitions(test_export_dataset PRIVATE
    ARI_EXPORT_DATASET_BIN="$<TARGET_FILE:export_dataset>")
  add_dependencies(test_export_dataset export_dataset)
endif()

# export_group_streams: what perception reports of random group scenes, as the CSV files of an
# F-formation data set for detect_groups (docs/perception_gcff.md, "GCFF on perceived streams").
add_executable(export_group_streams src/tools/export_group_streams.cpp)
target_link_libraries(export_group_streams ari_batch)
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
  # Issue 14: the engine and the nodes' cores composed as the nodes compose them, step by step.
  ari_add_gtest(test_live_batch_equivalence
    SOURCES test/nodes/test_live_batch_equivalence.cpp
    LIBRARIES ari_episode_bag ari_audio)
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
