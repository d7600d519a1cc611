// LeanMultiBodySolver and JointServo leave out rows that cannot carry an impulse; the simulation
// must come out exactly as with Bullet's own solver and joint motor.

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <BulletDynamics/Featherstone/btMultiBodyJointMotor.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>
#include <btBulletDynamicsCommon.h>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "joint_servo.hpp"
#include "lean_multibody_solver.hpp"

namespace ari_social_sim::physics {
namespace {

// A 10 kg box resting on two frictionless spheres (ARI's casters) and a driven wheel with
// friction, with a servoed arm on top: frictional and frictionless contacts, and servos.
struct Rig {
  explicit Rig(bool lean) {
    solver = lean ? std::make_unique<LeanMultiBodySolver>()
                  : std::make_unique<btMultiBodyConstraintSolver>();
    world = std::make_unique<btMultiBodyDynamicsWorld>(&dispatcher, &broadphase, solver.get(),
                                                       &collision_config);
    world->setGravity(btVector3(0, 0, -9.81));
    world->getSolverInfo().m_numIterations = 6;
    world->getSolverInfo().m_solverMode |= SOLVER_DISABLE_IMPLICIT_CONE_FRICTION;
    floor.setCollisionShape(&plane);
    floor.setFriction(1.0);
    world->addCollisionObject(&floor, btBroadphaseProxy::StaticFilter,
                              btBroadphaseProxy::DefaultFilter);

    body = std::make_unique<btMultiBody>(2, 10.0, btVector3(0.2, 0.3, 0.4), false, false);
    body->setBaseWorldTransform(btTransform(btQuaternion::getIdentity(), btVector3(0, 0, 0.3)));
    const btQuaternion none = btQuaternion::getIdentity();
    // Link 0: the wheel, spinning about y, 0.1 m below the base's centre at its front.
    body->setupRevolute(0, 1.0, btVector3(0.01, 0.01, 0.01), -1, none, btVector3(0, 1, 0),
                        btVector3(0.3, 0, -0.2), btVector3(0, 0, 0), true);
    // Link 1: an arm on top, swinging about x.
    body->setupRevolute(1, 2.0, btVector3(0.05, 0.05, 0.01), -1, none, btVector3(1, 0, 0),
                        btVector3(0, 0, 0.2), btVector3(0, 0, 0.25), true);
    body->finalizeMultiDof();
    body->setHasSelfCollision(false);
    world->addMultiBody(body.get());

    // The base carries two frictionless casters at its back.
    for (const double y : {-0.2, 0.2}) {
      base_shape.addChildShape(btTransform(none, btVector3(-0.3, y, -0.2)), &caster);
    }
    add_collider(-1, &base_shape, 0.0);
    add_collider(0, &wheel, 1.0);

    for (int link = 0; link < 2; ++link) {
      const double max_impulse = 0.02;  // 20 N m over 1 ms
      std::unique_ptr<btMultiBodyJointMotor> motor =
          lean ? std::make_unique<JointServo>(body.get(), link, max_impulse)
               : std::make_unique<btMultiBodyJointMotor>(body.get(), link, 0.0, max_impulse);
      world->addMultiBodyConstraint(motor.get());
      motors.push_back(std::move(motor));
    }
  }

  ~Rig() {
    for (auto& motor : motors) {
      world->removeMultiBodyConstraint(motor.get());
    }
    for (auto& collider : colliders) {
      world->removeCollisionObject(collider.get());
    }
    world->removeMultiBody(body.get());
    world->removeCollisionObject(&floor);
  }

  void add_collider(int link, btCollisionShape* shape, double friction) {
    auto collider = std::make_unique<btMultiBodyLinkCollider>(body.get(), link);
    collider->setCollisionShape(shape);
    collider->setFriction(friction);
    body->forwardKinematics(scratch_q, scratch_m);
    collider->setWorldTransform(link < 0 ? body->getBaseWorldTransform()
                                         : body->getLink(link).m_cachedWorldTransform);
    world->addCollisionObject(collider.get(), btBroadphaseProxy::DefaultFilter,
                              btBroadphaseProxy::StaticFilter);
    if (link < 0) {
      body->setBaseCollider(collider.get());
    } else {
      body->getLink(link).m_collider = collider.get();
    }
    colliders.push_back(std::move(collider));
  }

  // 1.5 s at 1 kHz: the wheel drives forward, the arm swings out and back.
  void run() {
    for (int step = 0; step < 1500; ++step) {
      const double t = step * 0.001;
      motors[0]->setVelocityTarget(4.0, 1.0);
      motors[1]->setPositionTarget(t < 0.75 ? 0.8 : -0.4, 0.2);
      motors[1]->setVelocityTarget(0.0, 1.0);
      world->stepSimulation(0.001, 0, 0.001);
    }
  }

  btDefaultCollisionConfiguration collision_config;
  btCollisionDispatcher dispatcher{&collision_config};
  btDbvtBroadphase broadphase;
  std::unique_ptr<btMultiBodyConstraintSolver> solver;
  std::unique_ptr<btMultiBodyDynamicsWorld> world;
  btStaticPlaneShape plane{btVector3(0, 0, 1), 0};
  btCollisionObject floor;
  btSphereShape caster{0.1};
  btSphereShape wheel{0.1};
  btCompoundShape base_shape;
  std::unique_ptr<btMultiBody> body;
  std::vector<std::unique_ptr<btMultiBodyLinkCollider>> colliders;
  std::vector<std::unique_ptr<btMultiBodyJointMotor>> motors;
  btAlignedObjectArray<btQuaternion> scratch_q;
  btAlignedObjectArray<btVector3> scratch_m;
};

TEST(LeanMultiBodySolver, GivesBulletsResultToTheBit) {
  Rig stock(false);
  Rig lean(true);
  stock.run();
  lean.run();

  // The scene did what it is for: it rolled forward on its wheel and casters, and the arm moved.
  const btVector3 position = lean.body->getBasePos();
  EXPECT_GT(position.x(), 0.05);
  EXPECT_NEAR(position.z(), 0.3, 0.05);  // on its wheel and casters, not through the floor
  EXPECT_NEAR(lean.body->getJointPos(1), -0.4, 0.05);
  EXPECT_GT(std::abs(lean.motors[1]->getAppliedImpulse(0)), 0.0);

  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_EQ(stock.body->getBasePos()[axis], position[axis]) << "axis " << axis;
    EXPECT_EQ(stock.body->getBaseVel()[axis], lean.body->getBaseVel()[axis]) << "axis " << axis;
    EXPECT_EQ(stock.body->getBaseOmega()[axis], lean.body->getBaseOmega()[axis]) << "axis " << axis;
  }
  for (int link = 0; link < 2; ++link) {
    EXPECT_EQ(stock.body->getJointPos(link), lean.body->getJointPos(link)) << "link " << link;
    EXPECT_EQ(stock.body->getJointVel(link), lean.body->getJointVel(link)) << "link " << link;
    EXPECT_EQ(stock.motors[link]->getAppliedImpulse(0), lean.motors[link]->getAppliedImpulse(0))
        << "link " << link;
  }
}

}  // namespace
}  // namespace ari_social_sim::physics
