# dialogue/: the Conversational Content Generator (multi-party user simulation), its tools, tests
# and benchmark. Everything runs on the repository's files alone; the MPGT corpus
# (docs/references.md#mpgt) is optional and found at run time, never at build time
# (docs/dialogue.md).
set(ARI_DIALOGUE_CONFIG_DIR "${CMAKE_CURRENT_SOURCE_DIR}/config/dialogue")

add_library(ari_dialogue
  src/dialogue/dialogue_act.cpp
  src/dialogue/goal.cpp
  src/dialogue/mpgt_corpus.cpp
  src/dialogue/domain.cpp
  src/dialogue/user_model.cpp
  src/dialogue/model_fitting.cpp
  src/dialogue/dialogue_stats.cpp
  src/dialogue/error_model.cpp
  src/dialogue/turn_timing.cpp
  src/dialogue/small_talk.cpp
  src/dialogue/template_text.cpp
  src/dialogue/nlg.cpp
  src/dialogue/agenda.cpp
  src/dialogue/user_simulation.cpp
  src/dialogue/reward.cpp
  src/dialogue/robot_action_request.cpp
  src/dialogue/dialogue_config.cpp
  src/dialogue/dialogue_env.cpp
  src/dialogue/rule_policy.cpp
  src/dialogue/dialogue_runner.cpp
  src/dialogue/json_lines.cpp
  src/dialogue/exemplar_index.cpp
  src/dialogue/robot_nlu.cpp
  src/dialogue/human_nlu.cpp
  src/dialogue/live_dialogue.cpp
  src/dialogue/dialogue_run_config.cpp
  src/dialogue/playback_stage.cpp
  src/dialogue/speech_playback.cpp
  src/dialogue/spoken_dialogue.cpp)
target_include_directories(ari_dialogue PUBLIC include)
target_link_libraries(ari_dialogue PUBLIC ari_core)
target_compile_definitions(ari_dialogue PRIVATE
  ARI_DIALOGUE_CONFIG_DIR="${ARI_DIALOGUE_CONFIG_DIR}")

add_executable(fit_dialogue_model src/tools/fit_dialogue_model.cpp)
target_link_libraries(fit_dialogue_model ari_dialogue)
add_executable(dialogue_corpus src/tools/dialogue_corpus.cpp)
target_link_libraries(dialogue_corpus ari_batch)

if(CATKIN_ENABLE_TESTING)
  # The programs themselves, run as a user would (test/tools/program_run.hpp).
  ari_add_gtest(test_dialogue_corpus SOURCES test/tools/test_dialogue_corpus.cpp
    LIBRARIES ari_core)
  target_compile_definitions(test_dialogue_corpus PRIVATE
    ARI_DIALOGUE_CORPUS_BIN="$<TARGET_FILE:dialogue_corpus>")
  add_dependencies(test_dialogue_corpus dialogue_corpus)
  ari_add_gtest(test_fit_dialogue_model SOURCES test/tools/test_fit_dialogue_model.cpp
    LIBRARIES ari_core)
  target_compile_definitions(test_fit_dialogue_model PRIVATE
    ARI_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
    ARI_FIT_DIALOGUE_MODEL_BIN="$<TARGET_FILE:fit_dialogue_model>")
  add_dependencies(test_fit_dialogue_model fit_dialogue_model)
endif()

if(CATKIN_ENABLE_TESTING)
  ari_add_gtest(test_dialogue
    SOURCES
      test/dialogue/test_dialogue_act.cpp
      test/dialogue/test_goal.cpp
      test/dialogue/test_mpgt_corpus.cpp
      test/dialogue/test_domain.cpp
      test/dialogue/test_user_model.cpp
      test/dialogue/test_model_fitting.cpp
      test/dialogue/test_dialogue_stats.cpp
      test/dialogue/test_error_model.cpp
      test/dialogue/test_turn_timing.cpp
      test/dialogue/test_template_text.cpp
      test/dialogue/test_nlg.cpp
      test/dialogue/test_agenda.cpp
      test/dialogue/test_reward.cpp
      test/dialogue/test_json_lines.cpp
      test/dialogue/test_dialogue_config.cpp
      test/dialogue/test_user_simulation.cpp
      test/dialogue/test_rule_policy.cpp
      test/dialogue/test_dialogue_env.cpp
      test/dialogue/test_dialogue_runner.cpp
      test/dialogue/test_robot_nlu.cpp
      test/dialogue/test_human_nlu.cpp
      test/dialogue/test_live_dialogue.cpp
      test/dialogue/test_dialogue_run_config.cpp
      test/dialogue/test_speech_playback.cpp
      test/dialogue/test_spoken_dialogue.cpp
    LIBRARIES ari_dialogue)
  target_compile_definitions(test_dialogue PRIVATE
    ARI_DIALOGUE_CONFIG_DIR="${ARI_DIALOGUE_CONFIG_DIR}")
endif()

# dialogue_node: thin ROS adapter over the dialogue core, three modes (docs/dialogue.md).
add_library(ari_dialogue_conversions src/dialogue_conversions/dialogue.cpp)
target_link_libraries(ari_dialogue_conversions PUBLIC ari_dialogue ari_world ari_node_support)
add_executable(dialogue_node
  src/nodes/dialogue_node.cpp
  src/nodes/dialogue/asr_stage.cpp
  src/nodes/dialogue/live_dialogue_node.cpp
  src/nodes/dialogue/request_checks.cpp
  src/nodes/dialogue/rl_env_services.cpp
  src/nodes/dialogue/sim_say_client.cpp)
# The world stage (mode 1) is world_speech::WorldSpeechStage, fed /sim/world_state as world
# snapshots.
target_link_libraries(dialogue_node
  ari_dialogue_conversions ari_world_conversions ari_world_speech)

if(CATKIN_ENABLE_TESTING)
  add_rostest(test/integration/dialogue_world.test DEPENDENCIES dialogue_node world_node)
  add_rostest(test/integration/dialogue_user_bot.test DEPENDENCIES dialogue_node)
  add_rostest(test/integration/dialogue_rl_env.test DEPENDENCIES dialogue_node)
endif()

if(benchmark_FOUND)
  ari_add_benchmark(bench_dialogue SOURCES bench/bench_dialogue.cpp LIBRARIES ari_dialogue)
  target_compile_definitions(bench_dialogue PRIVATE
    ARI_DIALOGUE_CONFIG_DIR="${ARI_DIALOGUE_CONFIG_DIR}")
endif()
