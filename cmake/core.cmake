# core/: shared small things (seeded RNG, bounded file reading, strict YAML reading, command-line values and output
# files, angles, errors).
add_library(ari_core
  src/core/bounds.cpp
  src/core/command_line.cpp
  src/core/control_characters.cpp
  src/core/data_sets.cpp
  src/core/format_text.cpp
  src/core/json_string.cpp
  src/core/output_file.cpp
  src/core/parameter_table.cpp
  src/core/pending_file.cpp
  src/core/progress_journal.cpp
  src/core/rng.cpp
  src/core/sim_timer.cpp
  src/core/stop_signal.cpp
  src/core/text_file.cpp
  src/core/yaml_map.cpp)
target_include_directories(ari_core PUBLIC include)
target_link_libraries(ari_core PUBLIC Eigen3::Eigen yaml-cpp)

if(CATKIN_ENABLE_TESTING)
  ari_add_gtest(test_core
    SOURCES test/core/test_command_line.cpp test/core/test_config_fields.cpp
      test/core/test_const_pointer_view.cpp test/core/test_format_text.cpp
      test/core/test_json_string.cpp test/core/test_output_file.cpp test/core/test_pending_file.cpp
      test/core/test_pose2.cpp
      test/core/test_progress_journal.cpp test/core/test_rng.cpp test/core/test_rng_streams.cpp
      test/core/test_sim_timer.cpp test/core/test_stop_signal.cpp
      test/core/test_text_file.cpp test/core/test_yaml_map.cpp
    LIBRARIES ari_core)
endif()
