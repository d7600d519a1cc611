# audio/: what ARI's microphone array hears. Voices synthesised with espeak-ng, fitted to the
# world's word timing, carried to the array's four microphones over direct and reflected paths
# with a late tail and noise, the direction of a sound found again by SRP-PHAT, and speech
# recognised with pocketsphinx. ROS-free.
find_package(PkgConfig REQUIRED)
pkg_check_modules(ESPEAK_NG REQUIRED IMPORTED_TARGET espeak-ng)
# pocketsphinx.pc names /usr/include/sphinxbase, which Debian's multiarch layout does not have:
# the headers are found where they are.
find_path(POCKETSPHINX_INCLUDE_DIR pocketsphinx.h PATH_SUFFIXES pocketsphinx REQUIRED)
find_path(SPHINXBASE_INCLUDE_DIR sphinxbase/logmath.h PATH_SUFFIXES x86_64-linux-gnu
  ${CMAKE_LIBRARY_ARCHITECTURE} REQUIRED)
find_library(POCKETSPHINX_LIBRARY pocketsphinx REQUIRED)
find_library(SPHINXBASE_LIBRARY sphinxbase REQUIRED)
find_package(OpenCV REQUIRED COMPONENTS core)

add_library(ari_audio
  src/audio/array_mixer.cpp
  src/audio/audio_run_config.cpp
  src/audio/chunk_analysis.cpp
  src/audio/domain_grammar.cpp
  src/audio/late_reverb.cpp
  src/audio/resampler.cpp
  src/audio/room_acoustics.cpp
  src/audio/sound_localizer.cpp
  src/audio/speech_recognition_run_config.cpp
  src/audio/speech_recognizer.cpp
  src/audio/speech_synthesizer.cpp
  src/audio/time_stretch.cpp
  src/audio/timed_speech.cpp
  src/audio/voice.cpp
  src/audio/voice_tracks.cpp
  src/audio/world_audio.cpp)
target_include_directories(ari_audio PUBLIC ${OpenCV_INCLUDE_DIRS})
target_include_directories(ari_audio SYSTEM PRIVATE ${POCKETSPHINX_INCLUDE_DIR}
  ${SPHINXBASE_INCLUDE_DIR} ${SPHINXBASE_INCLUDE_DIR}/sphinxbase)
target_link_libraries(ari_audio PUBLIC ari_world ari_dialogue
  PRIVATE PkgConfig::ESPEAK_NG ${POCKETSPHINX_LIBRARY} ${SPHINXBASE_LIBRARY} opencv_core)

if(CATKIN_ENABLE_TESTING)
  ari_add_gtest(test_audio
    SOURCES
      test/audio/test_array_mixer.cpp
      test/audio/test_sound_localizer.cpp
      test/audio/test_speech_recognition_run_config.cpp
      test/audio/test_speech_recognizer.cpp
      test/audio/test_speech_synthesizer.cpp
      test/audio/test_voice.cpp
      test/audio/test_voice_tracks.cpp
      test/audio/test_world_audio.cpp
    LIBRARIES ari_audio)
  target_include_directories(test_audio PRIVATE ${PROJECT_SOURCE_DIR}/test/world)
  target_compile_definitions(test_audio PRIVATE ARI_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
endif()

# audio_node: thin ROS adapter over WorldAudio, ARI's /audio/* topics (launch/audio.launch).
add_executable(audio_node src/nodes/audio_node.cpp)
target_link_libraries(audio_node ari_audio ari_world_conversions)
install(TARGETS audio_node RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
if(CATKIN_ENABLE_TESTING)
  add_rostest(test/integration/audio_node.test DEPENDENCIES world_node audio_node)
endif()

# speech_recognition_node: pocketsphinx on /audio/channel0 as ROS4HRI voices (speech:=audio).
add_executable(speech_recognition_node src/nodes/speech_recognition_node.cpp)
target_link_libraries(speech_recognition_node ari_audio ari_scenario ari_node_support)
install(TARGETS speech_recognition_node RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
if(CATKIN_ENABLE_TESTING)
  foreach(seed 1 2)
    add_rostest(test/integration/group_discussion_audio.test ARGS seed:=${seed}
      DEPENDENCIES world_node hri_perception_node group_detection_node social_mpc_node
        dialogue_node scenario_node audio_node speech_recognition_node)
  endforeach()
  add_rostest(test/integration/waiting_room_audio.test
    DEPENDENCIES world_node hri_perception_node group_detection_node social_mpc_node
      dialogue_node scenario_node audio_node speech_recognition_node)
endif()

if(benchmark_FOUND)
  ari_add_benchmark(bench_audio SOURCES bench/bench_audio.cpp LIBRARIES ari_audio)
  # The scenes are the world tests' own (test/world/scene_builders.hpp).
  target_include_directories(bench_audio PRIVATE ${PROJECT_SOURCE_DIR}/test/world)
  target_compile_definitions(bench_audio PRIVATE ARI_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
endif()

# asr_benchmark: pocketsphinx's word error rate on the array's channel 0 by distance, noise and a
# second talker (docs/audio.md, "Speech recognition"); a program run by hand, not a test.
# doa_benchmark: the localiser's direction error in the shipped scenes (docs/audio.md, "Direction
# of arrival"); run by hand.
add_executable(doa_benchmark bench/doa_benchmark.cpp)
target_link_libraries(doa_benchmark ari_audio ari_engine)
target_compile_definitions(doa_benchmark PRIVATE ARI_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
set_target_properties(doa_benchmark PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/bench)

add_executable(asr_benchmark bench/asr_benchmark.cpp)
target_link_libraries(asr_benchmark ari_audio)
target_compile_definitions(asr_benchmark PRIVATE ARI_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
set_target_properties(asr_benchmark PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/bench)
