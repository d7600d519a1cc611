# physics/: ARI on Bullet (URDF -> btMultiBody, joint trajectory controllers, diff drive, IMU),
# ari_physics_node, tests and benchmark. Bullet is Debian's double-precision build.
find_package(urdfdom REQUIRED)
set(ari_bullet_libraries BulletDynamics-float64 BulletCollision-float64 LinearMath-float64)

add_library(ari_physics
  src/physics/ari_controllers.cpp
  src/physics/ari_physics.cpp
  src/physics/diff_drive_controller.cpp
  src/physics/lean_multibody_solver.cpp
  src/physics/imu_model.cpp
  src/physics/joint_servo.cpp
  src/physics/joint_trajectory.cpp
  src/physics/multibody_layout.cpp
  src/physics/people_reports.cpp
  src/physics/person_shape.cpp
  src/physics/physics_config.cpp
  src/physics/physics_run_config.cpp
  src/physics/point_head.cpp
  src/physics/point_head_goal.cpp
  src/physics/robot_model.cpp
  src/physics/static_scene.cpp
  src/physics/trajectory_controller.cpp
  src/physics/trajectory_request_check.cpp
  src/physics/wheel_odometry.cpp)
target_include_directories(ari_physics PUBLIC include)
target_include_directories(ari_physics SYSTEM PRIVATE /usr/include/bullet ${urdfdom_INCLUDE_DIRS})
target_compile_definitions(ari_physics PUBLIC BT_USE_DOUBLE_PRECISION)
target_link_libraries(ari_physics PUBLIC ari_world ${urdfdom_LIBRARIES} ${ari_bullet_libraries})

set(ari_urdf "${PROJECT_SOURCE_DIR}/urdf/ari.urdf")

# ari_physics_node: thin ROS adapter over the physics core.
add_executable(ari_physics_node
  src/nodes/ari_physics_node.cpp
  src/nodes/physics/camera_interface.cpp
  src/nodes/physics/controller_interface.cpp
  src/nodes/physics/joint_trajectory.cpp
  src/nodes/physics/odom_frame.cpp
  src/nodes/physics/point_head_interface.cpp)
# ari_rendering and ari_mapping: the cameras' cores (cmake/rendering.cmake).
target_link_libraries(ari_physics_node ari_physics ari_rendering ari_mapping ari_world_conversions)

if(CATKIN_ENABLE_TESTING)
  ari_add_gtest(test_physics
    SOURCES
      test/physics/test_robot_model.cpp
      test/physics/test_multibody_layout.cpp
      test/physics/test_joint_trajectory.cpp
      test/physics/test_trajectory_controller.cpp
      test/physics/test_trajectory_request_check.cpp
      test/physics/test_diff_drive_controller.cpp
      test/physics/test_wheel_odometry.cpp
      test/physics/test_imu_model.cpp
      test/physics/test_point_head.cpp
      test/physics/test_point_head_goal.cpp
      test/physics/test_static_scene.cpp
      test/physics/test_physics_config.cpp
      test/physics/test_ari_physics.cpp
      test/physics/test_lean_multibody_solver.cpp
      test/physics/test_people_reports.cpp
    LIBRARIES ari_physics)
  # The Bullet-level test builds its own worlds with the solver's private headers.
  target_include_directories(test_physics SYSTEM PRIVATE /usr/include/bullet)
  target_include_directories(test_physics PRIVATE src/physics)
  target_compile_definitions(test_physics PRIVATE ARI_URDF="${ari_urdf}"
    ARI_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
endif()

if(benchmark_FOUND)
  ari_add_benchmark(bench_physics SOURCES bench/bench_physics.cpp LIBRARIES ari_physics)
  target_compile_definitions(bench_physics PRIVATE ARI_URDF="${ari_urdf}"
    ARI_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
endif()

if(CATKIN_ENABLE_TESTING)
  add_rostest(test/integration/ari_physics_node.test DEPENDENCIES ari_physics_node)
  add_rostest(test/integration/point_head_lost_frame.test DEPENDENCIES ari_physics_node)
  add_rostest(test/integration/fuzz_physics.test DEPENDENCIES ari_physics_node)
  add_rostest(test/integration/world_3d.test DEPENDENCIES ari_physics_node world_node)
  add_rostest(test/integration/ari_cameras.test DEPENDENCIES ari_physics_node)
  add_rostest(test/integration/head_crops.test
    DEPENDENCIES ari_physics_node world_node hri_perception_node)
  add_rostest(test/integration/head_crops_walking.test
    DEPENDENCIES ari_physics_node world_node hri_perception_node)
endif()
