# rendering/: headless rendering (EGL + OpenGL, llvmpipe without a GPU), ARI's camera models and
# rig, the drawn people and their labels; mapping/: OctoMap mapping from depth images. ROS-free.
find_package(OpenGL REQUIRED COMPONENTS OpenGL EGL)
find_package(OpenCV REQUIRED COMPONENTS core imgproc imgcodecs)
find_package(octomap REQUIRED)

add_library(ari_rendering
  src/rendering/ari_cameras.cpp
  src/rendering/camera_model.cpp
  src/rendering/camera_rig.cpp
  src/rendering/camera_rig_config.cpp
  src/rendering/camera_sensor.cpp
  src/rendering/depth_image.cpp
  src/rendering/doorways.cpp
  src/rendering/drawn_people.cpp
  src/rendering/egl_context.cpp
  src/rendering/figure_regions.cpp
  src/rendering/floor_shade.cpp
  src/rendering/fisheye_renderer.cpp
  src/rendering/frame_motion.cpp
  src/rendering/furniture.cpp
  src/rendering/gl_program.cpp
  src/rendering/human_appearance.cpp
  src/rendering/human_figure.cpp
  src/rendering/image_labels.cpp
  src/rendering/lamp_light.cpp
  src/rendering/motion_blur.cpp
  src/rendering/multisample_target.cpp
  src/rendering/people_crops.cpp
  src/rendering/people_figures.cpp
  src/rendering/physics_primitives.cpp
  src/rendering/region_crops.cpp
  src/rendering/render_mesh.cpp
  src/rendering/renderer.cpp
  src/rendering/snapshot_cameras.cpp
  src/rendering/weight_shifts.cpp
  src/rendering/world_scene.cpp)
target_include_directories(ari_rendering PUBLIC ${OpenCV_INCLUDE_DIRS})
target_link_libraries(ari_rendering PUBLIC ari_physics ${OpenCV_LIBS} PRIVATE OpenGL::OpenGL OpenGL::EGL)

# Mapping needs depth images and poses: it uses the renderer's library for depth image encodings,
# and never renders.
add_library(ari_mapping src/mapping/octomap_mapper.cpp)
target_include_directories(ari_mapping PUBLIC ${OCTOMAP_INCLUDE_DIRS} ${OpenCV_INCLUDE_DIRS})
target_link_libraries(ari_mapping PUBLIC ari_rendering ${OCTOMAP_LIBRARIES})

if(CATKIN_ENABLE_TESTING)
  ari_add_gtest(test_rendering
    SOURCES
      test/rendering/test_camera_model.cpp
      test/rendering/test_camera_sensor.cpp
      test/rendering/test_ari_cameras.cpp
      test/rendering/test_camera_rig.cpp
      test/rendering/test_depth_image.cpp
      test/rendering/test_doorways.cpp
      test/rendering/test_drawn_people.cpp
      test/rendering/test_figure_regions.cpp
      test/rendering/test_floor_shade.cpp
      test/rendering/test_fisheye_renderer.cpp
      test/rendering/test_furniture.cpp
      test/rendering/test_human_figures.cpp
      test/rendering/test_motion_blur.cpp
      test/rendering/test_people_crops.cpp
      test/rendering/test_physics_primitives.cpp
      test/rendering/test_weight_shifts.cpp
      test/rendering/test_renderer.cpp
    LIBRARIES ari_rendering)
  target_compile_definitions(test_rendering PRIVATE ARI_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
    ARI_URDF="${PROJECT_SOURCE_DIR}/urdf/ari.urdf")
  ari_add_gtest(test_mapping SOURCES test/mapping/test_octomap_mapper.cpp LIBRARIES ari_mapping)
  target_compile_definitions(test_mapping PRIVATE ARI_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
endif()

if(CATKIN_ENABLE_TESTING)
  # Stock OpenCV detectors (HOG people, Haar faces from opencv-data) on the rendered people.
  find_package(OpenCV REQUIRED COMPONENTS objdetect)
  ari_add_gtest(test_detector_study
    SOURCES test/rendering/test_detector_study.cpp
    LIBRARIES ari_rendering opencv_objdetect)
  target_compile_definitions(test_detector_study PRIVATE ARI_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  # detector_study: the same detectors on the shipped scenarios' images (docs/cameras.md, "Stock
  # detectors in the shipped scenarios"); a program run by hand, about an hour on one core.
  add_executable(detector_study bench/detector_study.cpp)
  target_link_libraries(detector_study ari_engine ari_rendering opencv_objdetect)
  target_compile_definitions(detector_study PRIVATE ARI_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  set_target_properties(detector_study PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/bench)
  # lone_heads: the frontal cascades on lone turned heads, a quicker measure of a face change
  # (docs/cameras.md, "Eyes and nose bridge toned down"); about 10 minutes on one core.
  add_executable(lone_heads bench/lone_heads.cpp)
  target_link_libraries(lone_heads ari_rendering opencv_objdetect)
  target_compile_definitions(lone_heads PRIVATE ARI_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  set_target_properties(lone_heads PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/bench)
  # Their options are checked before any rendering (test_detector_study runs both with bad ones).
  add_dependencies(test_detector_study detector_study)
  add_dependencies(test_detector_study lone_heads)
  target_compile_definitions(test_detector_study PRIVATE
    ARI_DETECTOR_STUDY_BIN="$<TARGET_FILE:detector_study>"
    ARI_LONE_HEADS_BIN="$<TARGET_FILE:lone_heads>")
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
