# scenario/: scenario files (a scene plus a script) and the state machine that plays them; its
# tests.
add_library(ari_scenario
  src/scenario/agent_ref.cpp
  src/scenario/episode_metrics.cpp
  src/scenario/episode_report.cpp
  src/scenario/random_group.cpp
  src/scenario/scenario.cpp
  src/scenario/script_runner.cpp
  src/scenario/transcript.cpp)
target_link_libraries(ari_scenario PUBLIC ari_world)

if(CATKIN_ENABLE_TESTING)
  ari_add_gtest(test_scenario
    SOURCES
      test/scenario/test_agent_ref.cpp
      test/scenario/test_episode_metrics.cpp
      test/scenario/test_random_group.cpp
      test/scenario/test_scenario.cpp
      test/scenario/test_script_runner.cpp
      test/scenario/test_transcript.cpp
    LIBRARIES ari_scenario)
  target_compile_definitions(test_scenario PRIVATE ARI_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  target_include_directories(test_scenario PRIVATE ${PROJECT_SOURCE_DIR}/test/world)
endif()
