#include "ari_social_sim/physics/ari_physics.hpp"

#include <BulletCollision/CollisionShapes/btCompoundShape.h>
#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <BulletDynamics/Featherstone/btMultiBodyJointLimitConstraint.h>
#include <BulletDynamics/Featherstone/btMultiBodyJointMotor.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>
#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <unordered_map>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/core/check.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/rng_streams.hpp"
#include "ari_social_sim/physics/ari_controllers.hpp"
#include "ari_social_sim/physics/multibody_layout.hpp"
#include "ari_social_sim/world/walked_distance.hpp"
#include "joint_servo.hpp"
#include "lean_multibody_solver.hpp"

namespace ari_social_sim::physics {
namespace {

// Collision groups: ARI's shell meets everything; its wheels and casters only the floor (they sit
// inside the base's footprint, and as spheres they would otherwise rub walls the base clears).
constexpr int kRobotShell = 1 << 6;
constexpr int kRobotRoller = 1 << 7;
constexpr int kFloor = 1 << 8;
constexpr int kStatic = 1 << 9;
constexpr int kPeople = 1 << 10;
// Collision margin (m) of ARI's and the people's shapes: small, so contacts happen at the drawn
// surfaces; Bullet keeps it inside boxes and cylinders.
constexpr double kMargin = 0.002;
// People glide to their reported pose within this time (s); a person further off than
// kPersonTeleportM (m) was moved on purpose (spawned, set_pose) and is placed at once.
constexpr double kPersonCatchUpS = 0.1;
constexpr double kPersonTeleportM = 0.5;
// Sum of squared impulse changes (N^2 s^2) under which the solver's iterations stop early.
constexpr double kSolverResidualThreshold = 1e-7;
// How far (rad) a wheel's position target may lead the wheel: 2 cm of travel.
constexpr double kWheelWindupRad = 0.16;

btVector3 to_bt(const Eigen::Vector3d& v) {
  return btVector3(v.x(), v.y(), v.z());
}

Eigen::Vector3d to_eigen(const btVector3& v) {
  return {v.x(), v.y(), v.z()};
}

btTransform to_bt(const Eigen::Isometry3d& X) {
  const Eigen::Matrix3d& R = X.linear();
  return btTransform(
      btMatrix3x3(R(0, 0), R(0, 1), R(0, 2), R(1, 0), R(1, 1), R(1, 2), R(2, 0), R(2, 1), R(2, 2)),
      to_bt(Eigen::Vector3d(X.translation())));
}

Eigen::Isometry3d to_eigen(const btTransform& X) {
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  const btMatrix3x3& R = X.getBasis();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      out.linear()(r, c) = R[r][c];
    }
  }
  out.translation() = to_eigen(X.getOrigin());
  return out;
}

btQuaternion to_bt_quaternion(const Eigen::Matrix3d& R) {
  const Eigen::Quaterniond q(R);
  return btQuaternion(q.x(), q.y(), q.z(), q.w());
}

Eigen::Isometry3d planar_pose(const core::Pose2& pose) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.translation() = Eigen::Vector3d(pose.position.x(), pose.position.y(), 0.0);
  X.linear() = Eigen::AngleAxisd(pose.theta, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return X;
}

}  // namespace

struct AriPhysics::Engine {
  struct ControlledJoints {
    std::vector<size_t> joints;  // indices into joint_names
  };
  struct Passive {
    size_t joint;
    size_t follows;
    double lower_rad;
    double upper_rad;
  };
  struct Person {
    PersonState reported;       // the 2D world's last report
    double reported_at_s{0.0};  // physics time it arrived
    PersonState state;          // where the body is now
    std::unique_ptr<btDefaultMotionState> motion;
    std::unique_ptr<btRigidBody> body;
  };

  Engine(const RobotModel& robot_model, const model::WorldDescription& world,
         const core::Pose2& start, const PhysicsConfig& config);
  ~Engine();

  void build_world(const PhysicsConfig& config);
  // build_robot's stages, in order.
  void build_robot(const core::Pose2& start, const PhysicsConfig& config);
  void create_multibody(const core::Pose2& start);
  void index_movable_joints();
  void add_colliders(const PhysicsConfig& config);
  std::unique_ptr<btCompoundShape> collision_shape(const BodyLayout& body);
  void add_servos();
  size_t movable_joint(const std::string& name) const;
  void add_controllers();
  void add_drive_and_imu(const core::Pose2& start, const PhysicsConfig& config);
  // The stages of AriPhysics::step() that come before and after Bullet's, in order.
  void drive_wheels(double dt, const PhysicsConfig& config);
  void run_trajectory_controllers(double dt, const PhysicsConfig& config);
  void follow_passive_joints(double dt);
  void move_people(double dt);
  void step_bullet(double dt);
  void roll_casters(double dt);
  btCollisionShape* own(std::unique_ptr<btCollisionShape> shape) {
    shapes.push_back(std::move(shape));
    return shapes.back().get();
  }
  void add_static(btCollisionShape* shape, const Eigen::Isometry3d& X, int group, int mask,
                  double friction);
  const std::vector<Eigen::Isometry3d>& link_poses();
  double joint_position(size_t joint) const;
  double joint_velocity(size_t joint) const;
  Eigen::Vector3d point_velocity(const Eigen::Vector3d& point_map) const;
  void save_good_state();
  bool state_is_finite() const;
  void restore_good_state();

  RobotModel model;
  MultibodyLayout layout;
  StaticScene scene;
  PersonShapeConfig person_config;
  double step_s;

  std::unique_ptr<btDefaultCollisionConfiguration> collision_config;
  std::unique_ptr<btCollisionDispatcher> dispatcher;
  std::unique_ptr<btDbvtBroadphase> broadphase;
  std::unique_ptr<LeanMultiBodySolver> solver;
  std::unique_ptr<btMultiBodyDynamicsWorld> dynamics;
  std::vector<std::unique_ptr<btCollisionShape>> shapes;
  std::vector<std::unique_ptr<btCollisionObject>> statics;
  std::unique_ptr<btMultiBody> robot;
  std::vector<std::unique_ptr<btMultiBodyLinkCollider>> colliders;
  std::vector<std::unique_ptr<btMultiBodyConstraint>> constraints;
  std::vector<Person> people;
  btCollisionShape* person_shape{nullptr};  // shared by every person

  std::vector<std::string> joint_names;        // every movable joint, URDF order
  std::vector<int> joint_model_index;          // its index in model.joints()
  std::vector<int> joint_link;                 // its multibody link; -1 if kinematic
  std::vector<double> kinematic_position;      // rad, joints with no multibody link
  std::vector<double> kinematic_velocity;      // rad/s
  std::vector<btMultiBodyJointMotor*> motors;  // nullptr for kinematic joints
  std::unordered_map<std::string, size_t> joint_by_name;
  std::vector<std::unique_ptr<TrajectoryController>> controllers;
  std::vector<ControlledJoints> controlled;
  std::vector<Passive> passive;
  struct Caster {
    size_t joint;                   // index into joint_names
    Eigen::Vector3d position_root;  // wheel centre in the root link's frame
    double radius_m;
  };
  std::vector<Caster> casters;  // kinematic joints that roll with the base
  size_t left_wheel{0};
  size_t right_wheel{0};
  double wheel_targets[2] = {0.0, 0.0};  // rad, left and right
  DriveGeometry geometry;
  std::unique_ptr<DiffDriveController> drive;
  std::unique_ptr<WheelOdometry> odometry;
  std::unique_ptr<ImuModel> imu;
  ImuReading imu_reading;
  uint64_t imu_count{0};
  double next_imu_s{0.0};
  int imu_link{-1};

  double time_s{0.0};
  uint64_t steps{0};
  PhysicsDiagnostics diagnostics;

  // Scratch of btMultiBody::forwardKinematics and the link poses computed from it, valid for
  // one step.
  btAlignedObjectArray<btQuaternion> scratch_rotations;
  btAlignedObjectArray<btVector3> scratch_origins;
  std::vector<Eigen::Isometry3d> poses;
  uint64_t poses_step{~0ull};

  // The last finite state, put back if the multibody ever blows up.
  btTransform good_base;
  std::vector<double> good_positions;
};

AriPhysics::Engine::Engine(const RobotModel& robot_model, const model::WorldDescription& world,
                           const core::Pose2& start, const PhysicsConfig& config)
    : model(robot_model),
      layout(MultibodyLayout::of(robot_model,
                                 [] {
                                   const std::vector<std::string> names = ari_kinematic_joints();
                                   return std::set<std::string>(names.begin(), names.end());
                                 }())),
      scene(StaticScene::from_world(world)),
      person_config(config.person),
      step_s(config.step_s) {
  collision_config = std::make_unique<btDefaultCollisionConfiguration>();
  dispatcher = std::make_unique<btCollisionDispatcher>(collision_config.get());
  broadphase = std::make_unique<btDbvtBroadphase>();
  solver = std::make_unique<LeanMultiBodySolver>();
  dynamics = std::make_unique<btMultiBodyDynamicsWorld>(dispatcher.get(), broadphase.get(),
                                                        solver.get(), collision_config.get());
  dynamics->setGravity(btVector3(0.0, 0.0, -config.gravity_mps2));
  dynamics->getSolverInfo().m_numIterations = config.solver_iterations;
  // Stop iterating once the impulses have converged: most steps need far fewer than the cap.
  dynamics->getSolverInfo().m_leastSquaresResidualThreshold = kSolverResidualThreshold;
  // Two friction directions per contact (the classic pyramid) instead of the implicit cone:
  // cheaper, and with it a parked ARI drifts no more than with twice the iterations.
  dynamics->getSolverInfo().m_solverMode |= SOLVER_DISABLE_IMPLICIT_CONE_FRICTION;
  // Only awake objects get their bounding boxes updated: the robot and the people, not the room.
  dynamics->setForceUpdateAllAabbs(false);
  build_world(config);
  build_robot(start, config);
  // One shape for every person: a cylinder to the shoulders and the head's sphere.
  auto person = std::make_unique<btCompoundShape>();
  Eigen::Isometry3d X_body = Eigen::Isometry3d::Identity();
  X_body.translation().z() = 0.5 * person_config.shoulder_height_m;
  auto body = std::make_unique<btCylinderShapeZ>(btVector3(person_config.body_radius_m,
                                                           person_config.body_radius_m,
                                                           0.5 * person_config.shoulder_height_m));
  body->setMargin(kMargin);
  person->addChildShape(to_bt(X_body), own(std::move(body)));
  Eigen::Isometry3d X_head = Eigen::Isometry3d::Identity();
  X_head.translation().z() = person_config.head_centre_height_m;
  person->addChildShape(to_bt(X_head),
                        own(std::make_unique<btSphereShape>(person_config.head_radius_m)));
  person_shape = own(std::move(person));
}

AriPhysics::Engine::~Engine() {
  for (Person& person : people) {
    dynamics->removeRigidBody(person.body.get());
  }
  for (auto& constraint : constraints) {
    dynamics->removeMultiBodyConstraint(constraint.get());
  }
  for (auto& collider : colliders) {
    dynamics->removeCollisionObject(collider.get());
  }
  if (robot) {
    dynamics->removeMultiBody(robot.get());
  }
  for (auto& object : statics) {
    dynamics->removeCollisionObject(object.get());
  }
}

void AriPhysics::Engine::add_static(btCollisionShape* shape, const Eigen::Isometry3d& X, int group,
                                    int mask, double friction) {
  auto object = std::make_unique<btCollisionObject>();
  object->setCollisionShape(shape);
  object->setWorldTransform(to_bt(X));
  object->setFriction(friction);
  // Never moves: asleep, its bounding box is not recomputed every step (setForceUpdateAllAabbs
  // is off); a sleeping object still collides with the awake robot and people.
  object->setActivationState(ISLAND_SLEEPING);
  dynamics->addCollisionObject(object.get(), group, mask);
  statics.push_back(std::move(object));
}

void AriPhysics::Engine::build_world(const PhysicsConfig& config) {
  // The floor is the plane z = 0 everywhere: ARI cannot drive off the world's rectangle into a
  // void, and the walls say where the room ends.
  add_static(own(std::make_unique<btStaticPlaneShape>(btVector3(0, 0, 1), 0.0)),
             Eigen::Isometry3d::Identity(), kFloor, kRobotShell | kRobotRoller, 1.0);
  for (const SceneSolid& solid : scene.solids) {
    btCollisionShape* shape = nullptr;
    switch (solid.type) {
      case SceneSolid::Type::kBox:
        shape = own(std::make_unique<btBoxShape>(to_bt(Eigen::Vector3d(0.5 * solid.box_size_m))));
        break;
      case SceneSolid::Type::kCylinder:
        shape = own(std::make_unique<btCylinderShapeZ>(
            btVector3(solid.radius_m, solid.radius_m, 0.5 * solid.height_m)));
        break;
      case SceneSolid::Type::kPrism: {
        auto hull = std::make_unique<btConvexHullShape>();
        for (const Eigen::Vector2d& p : solid.footprint) {
          const Eigen::Vector3d local =
              solid.X_map_solid.inverse() * Eigen::Vector3d(p.x(), p.y(), 0.0);
          hull->addPoint(btVector3(local.x(), local.y(), -0.5 * solid.height_m), false);
          hull->addPoint(btVector3(local.x(), local.y(), 0.5 * solid.height_m), false);
        }
        hull->recalcLocalAabb();
        shape = own(std::move(hull));
        break;
      }
    }
    add_static(shape, solid.X_map_solid, kStatic, kRobotShell, config.body_friction);
  }
}

void AriPhysics::Engine::build_robot(const core::Pose2& start, const PhysicsConfig& config) {
  create_multibody(start);
  index_movable_joints();
  robot->finalizeMultiDof();
  robot->setLinearDamping(0.0);
  robot->setAngularDamping(0.0);
  robot->setHasSelfCollision(false);
  robot->setUseGyroTerm(true);
  dynamics->addMultiBody(robot.get());
  add_colliders(config);
  add_servos();
  add_controllers();
  add_drive_and_imu(start, config);
  save_good_state();
}

void AriPhysics::Engine::create_multibody(const core::Pose2& start) {
  const std::vector<BodyLayout>& bodies = layout.bodies();
  const int link_count = static_cast<int>(bodies.size()) - 1;
  const BodyLayout& root = bodies[0];
  robot = std::make_unique<btMultiBody>(link_count, root.mass_kg,
                                        to_bt(Eigen::Vector3d(root.principal_inertia_kgm2)),
                                        /*fixedBase=*/false, /*canSleep=*/false);
  robot->setBaseWorldTransform(to_bt(planar_pose(start) * root.X_reference_com));

  // One multibody link per movable joint, placed as Bullet's setupRevolute wants it: the pivot
  // from the parent's centre of mass in the parent's principal frame, the rotation from the
  // parent's principal frame to the child's at q = 0, and the axis in the child's principal frame.
  for (int k = 1; k <= link_count; ++k) {
    const BodyLayout& body = bodies[static_cast<size_t>(k)];
    const BodyLayout& parent = bodies[static_cast<size_t>(body.parent_body)];
    const RobotJoint& joint = model.joints()[static_cast<size_t>(body.joint)];
    const Eigen::Isometry3d X_parentref_joint =
        layout.placements()[static_cast<size_t>(joint.parent_link)].X_reference_link *
        joint.X_parent_joint;
    const Eigen::Isometry3d X_parentcom_joint =
        parent.X_reference_com.inverse() * X_parentref_joint;
    const Eigen::Isometry3d X_com_joint = body.X_reference_com.inverse();
    robot->setupRevolute(
        k - 1, body.mass_kg, to_bt(Eigen::Vector3d(body.principal_inertia_kgm2)),
        body.parent_body - 1,
        to_bt_quaternion(X_com_joint.linear() * X_parentcom_joint.linear().transpose()),
        to_bt(Eigen::Vector3d(X_com_joint.linear() * joint.axis)),
        to_bt(Eigen::Vector3d(X_parentcom_joint.translation())),
        to_bt(Eigen::Vector3d(-X_com_joint.translation())),
        /*disableParentCollision=*/true);
  }
}

// Every movable joint in URDF order, its multibody link (if simulated) and the casters among the
// kinematic ones.
void AriPhysics::Engine::index_movable_joints() {
  for (size_t j = 0; j < model.joints().size(); ++j) {
    const RobotJoint& joint = model.joints()[j];
    if (!joint.is_movable()) {
      continue;
    }
    const int body = layout.body_of_joint(static_cast<int>(j));
    joint_by_name[joint.name] = joint_names.size();
    joint_names.push_back(joint.name);
    joint_model_index.push_back(static_cast<int>(j));
    joint_link.push_back(body < 0 ? -1 : body - 1);
    const RobotLink& child = model.links()[static_cast<size_t>(joint.child_link)];
    if (layout.is_kinematic(static_cast<int>(j)) && joint.type == JointType::kContinuous &&
        layout.placements()[static_cast<size_t>(joint.child_link)].body == 0 &&
        !child.collisions.empty()) {
      casters.push_back({joint_names.size() - 1,
                         layout.placements()[static_cast<size_t>(joint.child_link)]
                             .X_reference_link.translation(),
                         child.collisions[0].radius_m});
    }
  }
  kinematic_position.assign(joint_names.size(), 0.0);
  kinematic_velocity.assign(joint_names.size(), 0.0);
}

// A body's URDF collision primitives in its principal frame. Links on continuous joints roll
// (wheels, casters): a sphere of the cylinder's radius gives one clean contact point with the
// floor instead of a cylinder rim's chattering ones.
std::unique_ptr<btCompoundShape> AriPhysics::Engine::collision_shape(const BodyLayout& body) {
  auto compound = std::make_unique<btCompoundShape>();
  for (const int link : body.links) {
    const Eigen::Isometry3d X_com_link =
        body.X_reference_com.inverse() *
        layout.placements()[static_cast<size_t>(link)].X_reference_link;
    const int parent_joint = model.links()[static_cast<size_t>(link)].parent_joint;
    const bool link_rolls =
        parent_joint >= 0 &&
        model.joints()[static_cast<size_t>(parent_joint)].type == JointType::kContinuous;
    for (const LinkShape& primitive : model.links()[static_cast<size_t>(link)].collisions) {
      std::unique_ptr<btCollisionShape> shape;
      if (link_rolls || primitive.type == LinkShape::Type::kSphere) {
        shape = std::make_unique<btSphereShape>(primitive.type == LinkShape::Type::kBox
                                                    ? 0.5 * primitive.box_size_m.minCoeff()
                                                    : primitive.radius_m);
      } else if (primitive.type == LinkShape::Type::kBox) {
        shape = std::make_unique<btBoxShape>(to_bt(Eigen::Vector3d(0.5 * primitive.box_size_m)));
      } else {
        shape = std::make_unique<btCylinderShapeZ>(
            btVector3(primitive.radius_m, primitive.radius_m, 0.5 * primitive.length_m));
      }
      shape->setMargin(std::min<btScalar>(kMargin, shape->getMargin()));
      compound->addChildShape(to_bt(X_com_link * primitive.X_link_shape), own(std::move(shape)));
    }
  }
  return compound;
}

void AriPhysics::Engine::add_colliders(const PhysicsConfig& config) {
  const std::vector<BodyLayout>& bodies = layout.bodies();
  const DriveJoints drive_joints;
  robot->forwardKinematics(scratch_rotations, scratch_origins);
  for (size_t k = 0; k < bodies.size(); ++k) {
    const BodyLayout& body = bodies[k];
    const bool rolls = body.joint >= 0 && model.joints()[static_cast<size_t>(body.joint)].type ==
                                              JointType::kContinuous;
    std::unique_ptr<btCompoundShape> compound = collision_shape(body);
    if (compound->getNumChildShapes() == 0) {
      continue;
    }
    auto collider = std::make_unique<btMultiBodyLinkCollider>(robot.get(), static_cast<int>(k) - 1);
    collider->setCollisionShape(own(std::move(compound)));
    const std::string joint_name =
        body.joint >= 0 ? model.joints()[static_cast<size_t>(body.joint)].name : "";
    const bool driven =
        joint_name == drive_joints.left_wheel || joint_name == drive_joints.right_wheel;
    // The base carries the casters, so its friction is theirs: its shell slides along walls.
    collider->setFriction(driven ? config.wheel_friction
                                 : (k == 0 ? config.caster_friction : config.body_friction));
    const btTransform X_world_com =
        k == 0 ? robot->getBaseWorldTransform()
               : robot->getLink(static_cast<int>(k) - 1).m_cachedWorldTransform;
    collider->setWorldTransform(X_world_com);
    if (rolls) {
      dynamics->addCollisionObject(collider.get(), kRobotRoller, kFloor);
    } else {
      // The base's casters meet the floor; no other shell reaches down to it.
      dynamics->addCollisionObject(collider.get(), kRobotShell,
                                   (k == 0 ? kFloor : 0) | kStatic | kPeople);
    }
    if (k == 0) {
      robot->setBaseCollider(collider.get());
    } else {
      robot->getLink(static_cast<int>(k) - 1).m_collider = collider.get();
    }
    colliders.push_back(std::move(collider));
  }
}

// A motor on every simulated joint with an effort limit (wheels, head, arms), capped at that
// effort. Position limits are kept by the controllers, which saturate every command.
void AriPhysics::Engine::add_servos() {
  for (size_t j = 0; j < joint_names.size(); ++j) {
    const RobotJoint& joint = model.joint(joint_names[j]);
    if (joint_link[j] >= 0 && joint.max_effort_nm > 0.0) {
      auto motor =
          std::make_unique<JointServo>(robot.get(), joint_link[j], joint.max_effort_nm * step_s);
      motors.push_back(motor.get());
      dynamics->addMultiBodyConstraint(motor.get());
      constraints.push_back(std::move(motor));
    } else {
      motors.push_back(nullptr);
    }
  }
}

size_t AriPhysics::Engine::movable_joint(const std::string& name) const {
  const auto it = joint_by_name.find(name);
  if (it == joint_by_name.end()) {
    throw core::RequestError(model.name() + ": the model has no movable joint '" + name +
                             "' that ARI's controllers need");
  }
  return it->second;
}

// ARI's trajectory controllers and the passive joints that follow them.
void AriPhysics::Engine::add_controllers() {
  for (const ControllerSpec& spec : ari_controller_specs()) {
    ControlledJoints owned;
    std::vector<JointBounds> bounds;
    for (const std::string& name : spec.joints) {
      owned.joints.push_back(movable_joint(name));
      const RobotJoint& joint = model.joint(name);
      bounds.push_back({joint.lower_rad, joint.upper_rad, joint.max_velocity_rps});
    }
    controllers.push_back(std::make_unique<TrajectoryController>(
        spec, bounds, std::vector<double>(spec.joints.size(), 0.0)));
    controlled.push_back(owned);
  }
  for (const PassiveJoint& joint : ari_passive_joints()) {
    const RobotJoint& robot_joint = model.joint(joint.joint);
    passive.push_back({movable_joint(joint.joint), movable_joint(joint.follows),
                       robot_joint.lower_rad, robot_joint.upper_rad});
  }
}

void AriPhysics::Engine::add_drive_and_imu(const core::Pose2& start, const PhysicsConfig& config) {
  const DriveJoints drive_joints;
  left_wheel = movable_joint(drive_joints.left_wheel);
  right_wheel = movable_joint(drive_joints.right_wheel);
  // Radius from the wheel's collision cylinder, separation from the joint origins, as PAL's
  // diff_drive_controller reads them from the URDF.
  const RobotJoint& left = model.joint(drive_joints.left_wheel);
  const RobotJoint& right = model.joint(drive_joints.right_wheel);
  const RobotLink& wheel_link = model.links()[static_cast<size_t>(left.child_link)];
  if (wheel_link.collisions.empty() ||
      wheel_link.collisions[0].type != LinkShape::Type::kCylinder) {
    throw core::RequestError(model.name() + ": " + wheel_link.name +
                             " needs a cylinder collision (the wheel radius)");
  }
  geometry.wheel_radius_m = wheel_link.collisions[0].radius_m;
  geometry.wheel_separation_m =
      (left.X_parent_joint.translation() - right.X_parent_joint.translation()).norm();
  drive = std::make_unique<DiffDriveController>(config.base_limits, geometry);
  odometry = std::make_unique<WheelOdometry>(geometry, start);
  imu_link = model.link_index(AriPhysics::kImuFrame);
  if (imu_link < 0) {
    throw core::RequestError(model.name() + ": no frame '" + std::string(AriPhysics::kImuFrame) +
                             "' for the torso IMU");
  }
  imu = std::make_unique<ImuModel>(config.imu_noise, config.gravity_mps2,
                                   core::rng_for(config.seed, core::rng_streams::kImuNoise));
}

// The diff-drive controller's wheel velocities, and the wheel angles they integrate to as the
// position target, which plays the wheel PID's integral term: without it a parked ARI creeps
// (0.3 mm/s) on the solver's residual. The target never leads the wheel by more than
// kWheelWindupRad, so a wheel held by a wall does not wind up a lunge for later.
void AriPhysics::Engine::drive_wheels(double dt, const PhysicsConfig& config) {
  drive->update(time_s, dt);
  const double wheel_rates[2] = {drive->left_wheel_rps(), drive->right_wheel_rps()};
  const size_t wheels[2] = {left_wheel, right_wheel};
  for (int w = 0; w < 2; ++w) {
    const double angle = joint_position(wheels[w]);
    wheel_targets[w] = std::clamp(wheel_targets[w] + wheel_rates[w] * dt, angle - kWheelWindupRad,
                                  angle + kWheelWindupRad);
    motors[wheels[w]]->setVelocityTarget(wheel_rates[w], 1.0);
    motors[wheels[w]]->setPositionTarget(wheel_targets[w], config.joint_position_gain);
  }
}

// The saturated position command of each trajectory controller, and its rate as the servo's
// velocity target.
void AriPhysics::Engine::run_trajectory_controllers(double dt, const PhysicsConfig& config) {
  std::vector<double> q;
  std::vector<double> qd;
  for (size_t c = 0; c < controllers.size(); ++c) {
    TrajectoryController& controller = *controllers[c];
    const std::vector<size_t>& joints = controlled[c].joints;
    q.resize(joints.size());
    qd.resize(joints.size());
    for (size_t j = 0; j < joints.size(); ++j) {
      q[j] = joint_position(joints[j]);
      qd[j] = joint_velocity(joints[j]);
    }
    const std::vector<double> previous = controller.command();
    controller.update(time_s, dt, q, qd);
    for (size_t j = 0; j < joints.size(); ++j) {
      const double rate = (controller.command()[j] - previous[j]) / dt;
      if (btMultiBodyJointMotor* motor = motors[joints[j]]) {
        motor->setPositionTarget(controller.command()[j], config.joint_position_gain);
        motor->setVelocityTarget(rate, config.joint_velocity_gain);
      } else {
        kinematic_position[joints[j]] = controller.command()[j];
        kinematic_velocity[joints[j]] = rate;
      }
    }
  }
}

// Passive finger joints copy the actuated one, within their own limits.
void AriPhysics::Engine::follow_passive_joints(double dt) {
  for (const Passive& joint : passive) {
    const double next =
        std::clamp(kinematic_position[joint.follows], joint.lower_rad, joint.upper_rad);
    kinematic_velocity[joint.joint] = (next - kinematic_position[joint.joint]) / dt;
    kinematic_position[joint.joint] = next;
  }
}

// People walk on at their reported velocity and close the gap to where their last report puts
// them now within kPersonCatchUpS, so a body never jumps: a kinematic body that jumps into ARI
// would hit it with the jump's speed.
void AriPhysics::Engine::move_people(double dt) {
  for (Person& person : people) {
    const double since = time_s - person.reported_at_s;
    const Eigen::Vector2d expected =
        person.reported.pose.position + since * person.reported.velocity_mps;
    const double expected_theta =
        person.reported.pose.theta + since * person.reported.angular_velocity_rps;
    const Eigen::Vector2d glide_mps =
        person.reported.velocity_mps + (expected - person.state.pose.position) / kPersonCatchUpS;
    const double turn_rps =
        person.reported.angular_velocity_rps +
        core::angle_difference(expected_theta, person.state.pose.theta) / kPersonCatchUpS;
    // The glide moves the body only: the state keeps the report's velocities (set_people), the
    // world's walk, whose speed sets the figure's stride as it does in rendering::DrawnPeople.
    person.state.pose.position += dt * glide_mps;
    person.state.pose.theta += dt * turn_rps;
    // The gait goes on from the report's as the world's would: walking on at its speed.
    person.state.walked_m = world::walked_on(person.reported.walked_m, person.reported.velocity_mps,
                                             person.reported.seated_fraction, since + dt);
    person.motion->setWorldTransform(to_bt(planar_pose(person.state.pose)));
  }
}

// Bullet's step; a state that blew up is replaced by the last finite one.
void AriPhysics::Engine::step_bullet(double dt) {
  dynamics->stepSimulation(dt, 0, dt);
  if (!state_is_finite()) {
    restore_good_state();
  } else if (steps % 100 == 0) {
    save_good_state();
  }
  time_s = static_cast<double>(steps + 1) * dt;
  ++steps;
}

// Casters roll with the floor under them.
void AriPhysics::Engine::roll_casters(double dt) {
  if (casters.empty()) {
    return;
  }
  // Casters ride on the base (body 0), whose pose alone places them.
  const Eigen::Isometry3d X_map_root =
      to_eigen(robot->getBaseWorldTransform()) * layout.bodies()[0].X_reference_com.inverse();
  for (const Caster& caster : casters) {
    // Positive spin rolls forward, as the wheels' (the same joint axis).
    const double forward = point_velocity(X_map_root * caster.position_root)
                               .dot(X_map_root.linear() * Eigen::Vector3d::UnitX());
    kinematic_velocity[caster.joint] = forward / caster.radius_m;
    kinematic_position[caster.joint] += kinematic_velocity[caster.joint] * dt;
  }
}

const std::vector<Eigen::Isometry3d>& AriPhysics::Engine::link_poses() {
  if (poses_step == steps) {
    return poses;
  }
  robot->forwardKinematics(scratch_rotations, scratch_origins);
  poses.resize(model.links().size());
  // Parents first: a simulated joint's link from its body's pose, any other from its parent.
  for (size_t link = 0; link < poses.size(); ++link) {
    const int parent_joint = model.links()[link].parent_joint;
    const int body = layout.placements()[link].body;
    const BodyLayout& layout_body = layout.bodies()[static_cast<size_t>(body)];
    if (parent_joint < 0 || layout_body.reference_link == static_cast<int>(link)) {
      const btTransform X_world_com = body == 0 ? robot->getBaseWorldTransform()
                                                : robot->getLink(body - 1).m_cachedWorldTransform;
      poses[link] = to_eigen(X_world_com) * layout_body.X_reference_com.inverse();
      continue;
    }
    const RobotJoint& joint = model.joints()[static_cast<size_t>(parent_joint)];
    const auto kinematic = joint_by_name.find(joint.name);
    const double q = kinematic == joint_by_name.end() ? 0.0 : kinematic_position[kinematic->second];
    poses[link] = poses[static_cast<size_t>(joint.parent_link)] * model.joint_transform(joint, q);
  }
  poses_step = steps;
  return poses;
}

double AriPhysics::Engine::joint_position(size_t joint) const {
  return joint_link[joint] < 0 ? kinematic_position[joint] : robot->getJointPos(joint_link[joint]);
}

double AriPhysics::Engine::joint_velocity(size_t joint) const {
  return joint_link[joint] < 0 ? kinematic_velocity[joint] : robot->getJointVel(joint_link[joint]);
}

Eigen::Vector3d AriPhysics::Engine::point_velocity(const Eigen::Vector3d& point_map) const {
  const Eigen::Vector3d com = to_eigen(robot->getBasePos());
  return to_eigen(robot->getBaseVel()) + to_eigen(robot->getBaseOmega()).cross(point_map - com);
}

void AriPhysics::Engine::save_good_state() {
  good_base = robot->getBaseWorldTransform();
  good_positions.resize(static_cast<size_t>(robot->getNumLinks()));
  for (int i = 0; i < robot->getNumLinks(); ++i) {
    good_positions[static_cast<size_t>(i)] = robot->getJointPos(i);
  }
}

bool AriPhysics::Engine::state_is_finite() const {
  const btVector3 p = robot->getBasePos();
  const btVector3 v = robot->getBaseVel();
  if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()) ||
      !std::isfinite(v.x()) || !std::isfinite(v.y()) || !std::isfinite(v.z())) {
    return false;
  }
  for (int i = 0; i < robot->getNumLinks(); ++i) {
    if (!std::isfinite(robot->getJointPos(i)) || !std::isfinite(robot->getJointVel(i))) {
      return false;
    }
  }
  return true;
}

void AriPhysics::Engine::restore_good_state() {
  robot->setBaseWorldTransform(good_base);
  robot->setBaseVel(btVector3(0, 0, 0));
  robot->setBaseOmega(btVector3(0, 0, 0));
  for (int i = 0; i < robot->getNumLinks(); ++i) {
    robot->setJointPos(i, good_positions[static_cast<size_t>(i)]);
    robot->setJointVel(i, 0.0);
  }
  ++diagnostics.nan_resets;
}

// ---------------------------------------------------------------------------------------------

AriPhysics::AriPhysics(const RobotModel& model, const model::WorldDescription& world,
                       const core::Pose2& start, const PhysicsConfig& config)
    : config_(config) {
  config_.validate();
  engine_ = std::make_unique<Engine>(model, world, start, config_);
}

AriPhysics::~AriPhysics() = default;

void AriPhysics::step() {
  Engine& e = *engine_;
  const double dt = config_.step_s;
  e.drive_wheels(dt, config_);
  e.run_trajectory_controllers(dt, config_);
  e.follow_passive_joints(dt);
  e.move_people(dt);
  e.step_bullet(dt);
  e.roll_casters(dt);
  // Wheel odometry every step; the IMU at its rate.
  e.odometry->update(e.joint_position(e.left_wheel), e.joint_position(e.right_wheel),
                     e.joint_velocity(e.left_wheel), e.joint_velocity(e.right_wheel));
  if (e.time_s + 1e-9 >= e.next_imu_s) {
    const Eigen::Isometry3d X_map_imu = frame_pose(kImuFrame);
    e.imu_reading = e.imu->measure(e.time_s, X_map_imu, e.point_velocity(X_map_imu.translation()),
                                   to_eigen(e.robot->getBaseOmega()));
    ++e.imu_count;
    e.next_imu_s += 1.0 / config_.imu_rate_hz;
  }
}

double AriPhysics::time_s() const {
  return engine_->time_s;
}

uint64_t AriPhysics::step_count() const {
  return engine_->steps;
}

bool AriPhysics::command_base(double linear_mps, double angular_rps) {
  const bool clamped = engine_->drive->command(linear_mps, angular_rps, engine_->time_s);
  engine_->diagnostics.clamped_base_commands += clamped ? 1 : 0;
  return clamped;
}

TrajectoryController& AriPhysics::controller(const std::string& name) {
  for (auto& controller : engine_->controllers) {
    if (controller->spec().name == name) {
      return *controller;
    }
  }
  throw core::RequestError("no controller named '" + name + "'");
}

const std::vector<std::unique_ptr<TrajectoryController>>& AriPhysics::controllers() const {
  return engine_->controllers;
}

void AriPhysics::set_people(const std::vector<PersonState>& people) {
  Engine& e = *engine_;
  // Bodies are reused by position in the list; only the count changes the world.
  const size_t placed_before = e.people.size();
  while (e.people.size() > people.size()) {
    e.dynamics->removeRigidBody(e.people.back().body.get());
    e.people.pop_back();
  }
  while (e.people.size() < people.size()) {
    Engine::Person person;
    person.motion = std::make_unique<btDefaultMotionState>();
    btRigidBody::btRigidBodyConstructionInfo info(0.0, person.motion.get(), e.person_shape);
    info.m_friction = config_.body_friction;
    person.body = std::make_unique<btRigidBody>(info);
    person.body->setCollisionFlags(person.body->getCollisionFlags() |
                                   btCollisionObject::CF_KINEMATIC_OBJECT);
    person.body->setActivationState(DISABLE_DEACTIVATION);
    e.dynamics->addRigidBody(person.body.get(), kPeople, kRobotShell);
    e.people.push_back(std::move(person));
  }
  for (size_t i = 0; i < people.size(); ++i) {
    Engine::Person& person = e.people[i];
    const bool placed =
        i < placed_before && person.reported.id == people[i].id &&
        (person.state.pose.position - people[i].pose.position).norm() < kPersonTeleportM;
    person.reported = people[i];
    person.reported_at_s = e.time_s;
    const core::Pose2 keep = person.state.pose;
    person.state = people[i];
    if (placed) {
      person.state.pose = keep;  // glides there (step 4)
    } else {
      const btTransform X = to_bt(planar_pose(people[i].pose));
      person.motion->setWorldTransform(X);
      person.body->setWorldTransform(X);
    }
  }
}

const RobotModel& AriPhysics::model() const {
  return engine_->model;
}

const StaticScene& AriPhysics::scene() const {
  return engine_->scene;
}

std::vector<PersonState> AriPhysics::people_states() const {
  std::vector<PersonState> states;
  for (const Engine::Person& person : engine_->people) {
    states.push_back(person.state);
  }
  return states;
}

std::vector<PersonShape> AriPhysics::people() const {
  std::vector<PersonShape> shapes;
  for (const Engine::Person& person : engine_->people) {
    shapes.push_back(PersonShape::of(person.state, engine_->person_config));
  }
  return shapes;
}

std::vector<Eigen::Isometry3d> AriPhysics::link_poses() const {
  return engine_->link_poses();
}

Eigen::Isometry3d AriPhysics::frame_pose(const std::string& frame) const {
  Engine& e = *engine_;
  const int link = e.model.link_index(frame);
  if (link < 0) {
    throw core::RequestError("no frame named '" + frame + "' on ARI");
  }
  return e.link_poses()[static_cast<size_t>(link)];
}

core::Pose2 AriPhysics::base_pose() const {
  const Eigen::Isometry3d X = frame_pose(engine_->model.links()[0].name);
  return {X.translation().head<2>(), std::atan2(X.linear()(1, 0), X.linear()(0, 0))};
}

double AriPhysics::base_linear_mps() const {
  const Eigen::Isometry3d X = frame_pose(engine_->model.links()[0].name);
  return engine_->point_velocity(X.translation()).dot(X.linear().col(0));
}

double AriPhysics::base_angular_rps() const {
  return engine_->robot->getBaseOmega().z();
}

const WheelOdometry& AriPhysics::odometry() const {
  return *engine_->odometry;
}

const std::vector<std::string>& AriPhysics::joint_names() const {
  return engine_->joint_names;
}

std::vector<double> AriPhysics::joint_positions() const {
  std::vector<double> out;
  for (size_t j = 0; j < engine_->joint_names.size(); ++j) {
    out.push_back(engine_->joint_position(j));
  }
  return out;
}

std::vector<double> AriPhysics::joint_velocities() const {
  std::vector<double> out;
  for (size_t j = 0; j < engine_->joint_names.size(); ++j) {
    out.push_back(engine_->joint_velocity(j));
  }
  return out;
}

std::vector<double> AriPhysics::joint_efforts() const {
  std::vector<double> out;
  for (btMultiBodyJointMotor* motor : engine_->motors) {
    out.push_back(motor == nullptr ? 0.0 : motor->getAppliedImpulse(0) / config_.step_s);
  }
  return out;
}

double AriPhysics::joint_position(const std::string& joint) const {
  const auto it = engine_->joint_by_name.find(joint);
  if (it == engine_->joint_by_name.end()) {
    throw core::RequestError("no movable joint named '" + joint + "' on ARI");
  }
  return engine_->joint_position(it->second);
}

const ImuReading& AriPhysics::imu() const {
  return engine_->imu_reading;
}

uint64_t AriPhysics::imu_reading_count() const {
  return engine_->imu_count;
}

const PhysicsDiagnostics& AriPhysics::diagnostics() const {
  return engine_->diagnostics;
}

}  // namespace ari_social_sim::physics
