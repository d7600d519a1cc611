# audio/: what ARI's microphone array hears. Voices synthesised with espeak-ng, fitted to the
# world's word timing, carried to the array's four microphones over direct and reflected paths
# with a late tail and noise, and the direction of a sound found again by SRP-PHAT. ROS-free.
find_package(PkgConfig REQUIRED)
pkg_check_modules(ESPEAK_NG REQUIRED IMPORTED_TARGET espeak-ng)
find_package(OpenCV REQUIRED COMPONENTS core)

add_library(ari_audio
  src/audio/array_mixer.cpp
  src/audio/audio_run_config.cpp
  src/audio/late_reverb.cpp
  src/audio/resampler.cpp
  src/audio/room_acoustics.cpp
  src/audio/sound_localizer.cpp
  src/audio/speech_synthesizer.cpp
  src/audio/timed_speech.cpp
  src/audio/voice.cpp
  src/audio/world_audio.cpp)
target_include_directories(ari_audio PUBLIC ${OpenCV_INCLUDE_DIRS})
target_link_libraries(ari_audio PUBLIC ari_world PRIVATE PkgConfig::ESPEAK_NG opencv_core)

if(CATKIN_ENABLE_TESTING)
  ari_add_gtest(test_audio
    SOURCES
      test/audio/test_array_mixer.cpp
      test/audio/test_sound_localizer.cpp
      test/audio/test_speech_synthesizer.cpp
      test/audio/test_voice.cpp
      test/audio/test_world_audio.cpp
    LIBRARIES ari_audio)
  target_include_directories(test_audio PRIVATE ${PROJECT_SOURCE_DIR}/test/world)
endif()

# audio_node: thin ROS adapter over WorldAudio, ARI's /audio/* topics (launch/audio.launch).
add_executable(audio_node src/nodes/audio_node.cpp)
target_link_libraries(audio_node ari_audio ari_world_conversions)
install(TARGETS audio_node RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
if(CATKIN_ENABLE_TESTING)
  add_rostest(test/integration/audio_node.test DEPENDENCIES world_node audio_node)
endif()

if(benchmark_FOUND)
  ari_add_benchmark(bench_audio SOURCES bench/bench_audio.cpp LIBRARIES ari_audio)
  # The scenes are the world tests' own (test/world/scene_builders.hpp).
  target_include_directories(bench_audio PRIVATE ${PROJECT_SOURCE_DIR}/test/world)
endif()
