#pragma once

#include <BulletDynamics/Featherstone/btMultiBodyJointMotor.h>

namespace ari_social_sim::physics {

/// Bullet's joint motor (position and velocity targets, impulse capped) on one revolute joint of
/// a multibody, with one side instead of two.
///
/// btMultiBodyJointMotor names the multibody as both of its bodies, the second with an all-zero
/// Jacobian, so every step it computes the tree's response to that zero Jacobian too: half of the
/// cost of a servo row. A JointServo acts on the multibody alone and reacts against the fixed
/// solver body, which gives the same row, impulse and result. It needs LeanMultiBodySolver, which
/// always provides that fixed body.
class JointServo : public btMultiBodyJointMotor {
 public:
  JointServo(btMultiBody* body, int link, btScalar max_impulse);

  /// The multibody's island, as for Bullet's motor, whose second side is the same multibody.
  int getIslandIdB() const override;
  void createConstraintRows(btMultiBodyConstraintArray& rows, btMultiBodyJacobianData& data,
                            const btContactSolverInfo& info) override;
};

}  // namespace ari_social_sim::physics
