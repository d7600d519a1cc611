# perception/: GCFF F-formation groups, group ids, the F-formation data sets and their evaluation;
# the detect_groups tool.
add_library(ari_perception
  src/perception/fformation_dataset.cpp
  src/perception/gcff.cpp
  src/perception/group_evaluation.cpp
  src/perception/group_tracker.cpp)
target_include_directories(ari_perception PUBLIC include)
target_link_libraries(ari_perception PUBLIC ari_core)

# Lands in devel/lib/ari_social_sim, so `rosrun ari_social_sim detect_groups` finds it.
add_executable(detect_groups src/tools/detect_groups.cpp)
target_link_libraries(detect_groups ari_perception)
install(TARGETS detect_groups RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})

if(CATKIN_ENABLE_TESTING)
  # The development sets live in shared/ beside the repository (specs/algorithms.md 1.7).
  set(ari_fformation_dir ${CMAKE_CURRENT_SOURCE_DIR}/../shared/fformation)
  ari_add_gtest(test_perception
    SOURCES
      test/perception/test_fformation_dataset.cpp
      test/perception/test_gcff.cpp
      test/perception/test_gcff_reference.cpp
      test/perception/test_group_evaluation.cpp
      test/perception/test_group_tracker.cpp
    LIBRARIES ari_perception)
  target_compile_definitions(test_perception PRIVATE ARI_FFORMATION_DIR="${ari_fformation_dir}")

  ari_add_gtest(test_detect_groups SOURCES test/tools/test_detect_groups.cpp)
  target_compile_definitions(test_detect_groups PRIVATE
    ARI_FFORMATION_DIR="${ari_fformation_dir}"
    ARI_DETECT_GROUPS_BIN="$<TARGET_FILE:detect_groups>")
  add_dependencies(test_detect_groups detect_groups)
endif()

if(benchmark_FOUND)
  ari_add_benchmark(bench_perception
    SOURCES bench/bench_perception.cpp
    LIBRARIES ari_perception)
endif()
