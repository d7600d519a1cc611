# model/: the vocabulary every module shares and that needs no simulator: object ids, person
# attributes, the world description and its file, the occupancy grid, ARI's limits, footprint and
# sensor geometry (the cameras' mounts and lenses, shared by physics and perception),
# perception's tracked persons and where their bodies stand.
# The navigation core builds on it alone, so it could run on the real robot.
add_library(ari_model
  src/model/occupancy_grid.cpp
  src/model/shape_geometry.cpp
  src/model/tracked_person.cpp
  src/model/world_file.cpp)
target_link_libraries(ari_model PUBLIC ari_core)

if(CATKIN_ENABLE_TESTING)
  ari_add_gtest(test_model
    SOURCES test/model/test_ari_sensor_geometry.cpp test/model/test_tracked_person.cpp
            test/model/test_world_file.cpp
    LIBRARIES ari_model)
  target_include_directories(test_model PRIVATE test/world)
  target_compile_definitions(test_model PRIVATE ARI_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
endif()
