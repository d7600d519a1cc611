# physics/ cameras and mapping: headless rendering (EGL + OpenGL, llvmpipe without a GPU), ARI's
# camera models and rig, and OctoMap mapping from depth images. ROS-free.
find_package(OpenGL REQUIRED COMPONENTS OpenGL EGL)
find_package(OpenCV REQUIRED COMPONENTS core imgproc imgcodecs)
find_package(octomap REQUIRED)

add_library(ari_rendering
  src/physics/ari_cameras.cpp
  src/physics/camera_model.cpp
  src/physics/camera_rig.cpp
  src/physics/camera_rig_config.cpp
  src/physics/depth_image.cpp
  src/physics/drawn_people.cpp
  src/physics/egl_context.cpp
  src/physics/fisheye_renderer.cpp
  src/physics/human_appearance.cpp
  src/physics/human_figure.cpp
  src/physics/figure_regions.cpp
  src/physics/image_labels.cpp
  src/physics/region_crops.cpp
  src/physics/people_crops.cpp
  src/physics/people_figures.cpp
  src/physics/physics_primitives.cpp
  src/physics/render_mesh.cpp
  src/physics/renderer.cpp
  src/physics/snapshot_cameras.cpp
  src/physics/world_scene.cpp)
target_include_directories(ari_rendering PUBLIC ${OpenCV_INCLUDE_DIRS})
target_link_libraries(ari_rendering PUBLIC ari_physics ${OpenCV_LIBS} PRIVATE OpenGL::OpenGL OpenGL::EGL)

# Mapping only needs depth images and poses, so it links OctoMap and not the renderer.
add_library(ari_mapping src/physics/octomap_mapper.cpp)
target_include_directories(ari_mapping PUBLIC ${OCTOMAP_INCLUDE_DIRS} ${OpenCV_INCLUDE_DIRS})
target_link_libraries(ari_mapping PUBLIC ari_rendering ${OCTOMAP_LIBRARIES})

if(CATKIN_ENABLE_TESTING)
  ari_add_gtest(test_cameras
    SOURCES
      test/physics/test_camera_model.cpp
      test/physics/test_ari_cameras.cpp
      test/physics/test_camera_rig.cpp
      test/physics/test_depth_image.cpp
      test/physics/test_drawn_people.cpp
      test/physics/test_figure_regions.cpp
      test/physics/test_fisheye_renderer.cpp
      test/physics/test_human_figures.cpp
      test/physics/test_octomap_mapper.cpp
      test/physics/test_people_crops.cpp
      test/physics/test_physics_primitives.cpp
      test/physics/test_renderer.cpp
    LIBRARIES ari_rendering ari_mapping)
  target_compile_definitions(test_cameras PRIVATE ARI_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
    ARI_URDF="${PROJECT_SOURCE_DIR}/urdf/ari.urdf")
endif()

if(CATKIN_ENABLE_TESTING)
  # Stock OpenCV detectors (HOG people, Haar faces from opencv-data) on the rendered people.
  find_package(OpenCV REQUIRED COMPONENTS objdetect)
  ari_add_gtest(test_detector_study
    SOURCES test/physics/test_detector_study.cpp
    LIBRARIES ari_rendering opencv_objdetect)
  target_compile_definitions(test_detector_study PRIVATE ARI_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
endif()

add_executable(render_cameras src/tools/render_cameras.cpp)
target_link_libraries(render_cameras ari_rendering)
if(CATKIN_ENABLE_TESTING)
  ari_add_gtest(test_render_cameras SOURCES test/tools/test_render_cameras.cpp)
  target_compile_definitions(test_render_cameras PRIVATE
    ARI_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
    ARI_RENDER_CAMERAS_BIN="$<TARGET_FILE:render_cameras>")
  add_dependencies(test_render_cameras render_cameras)
endif()

if(benchmark_FOUND)
  ari_add_benchmark(bench_cameras
    SOURCES bench/bench_cameras.cpp
    LIBRARIES ari_rendering ari_mapping)
  target_compile_definitions(bench_cameras PRIVATE ARI_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
endif()
