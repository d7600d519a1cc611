# docs/parameters.md, generated from the config structs of every module by parameter_docs, and the
# test that keeps the committed page up to date.
add_library(ari_parameters_page src/parameters_page/parameters_page.cpp)
target_include_directories(ari_parameters_page PUBLIC ${PROJECT_SOURCE_DIR}/src)
target_link_libraries(ari_parameters_page PUBLIC ari_engine ari_learning ari_audio ari_physics ari_rendering
  ari_mapping)

add_executable(parameter_docs src/tools/parameter_docs/parameter_docs.cpp)
target_link_libraries(parameter_docs ari_parameters_page)

if(CATKIN_ENABLE_TESTING)
  ari_add_gtest(test_parameter_docs
    SOURCES test/tools/test_parameter_docs.cpp
    LIBRARIES ari_parameters_page)
  target_compile_definitions(test_parameter_docs PRIVATE ARI_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
endif()
