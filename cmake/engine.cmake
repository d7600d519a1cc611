# world_speech/: the world's speakers as a dialogue stage (WorldSpeechStage), the world stage of
# dialogue_node and of the engine: a library of its own so that dialogue_node links neither
# perception nor navigation.
add_library(ari_world_speech src/world_speech/small_talk_lines.cpp src/world_speech/world_speech_stage.cpp)
target_link_libraries(ari_world_speech PUBLIC ari_dialogue ari_world)

# engine/: the in-process engine. Episode runs a scenario's script against the world, perception,
# navigation and dialogue cores in one process, in sim time, for the batch tools and the learning
# environments.
add_library(ari_engine
  src/engine/ari_observation.cpp
  src/engine/episode.cpp
  src/engine/in_process_navigation.cpp)
target_link_libraries(ari_engine PUBLIC ari_scenario ari_navigation ari_world_speech)

if(CATKIN_ENABLE_TESTING)
  ari_add_gtest(test_engine
    SOURCES
      test/engine/test_episode_config.cpp
      test/engine/test_episode_requests.cpp
      test/engine/test_recognised_hearing.cpp
    LIBRARIES ari_engine)
  target_compile_definitions(test_engine PRIVATE ARI_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  target_include_directories(test_engine PRIVATE ${PROJECT_SOURCE_DIR}/test/world)

  ari_add_gtest(test_conversation
    SOURCES test/world_speech/test_group_conversation.cpp
    LIBRARIES ari_world_speech)
  target_compile_definitions(test_conversation PRIVATE ARI_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  target_include_directories(test_conversation PRIVATE ${PROJECT_SOURCE_DIR}/test/world)
endif()
