#include "joint_servo.hpp"

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

#include "ari_social_sim/core/check.hpp"

namespace ari_social_sim::physics {

JointServo::JointServo(btMultiBody* body, int link, btScalar max_impulse)
    : btMultiBodyJointMotor(body, link, /*linkDoF=*/0, /*desiredVelocity=*/0, max_impulse) {
  m_bodyB = nullptr;
  m_linkB = -1;
}

int JointServo::getIslandIdB() const {
  // All colliders of one multibody share its island; the joint's own link may have none.
  if (const btMultiBodyLinkCollider* base = m_bodyA->getBaseCollider()) {
    return base->getIslandTag();
  }
  for (int link = 0; link < m_bodyA->getNumLinks(); ++link) {
    if (const btMultiBodyLinkCollider* collider = m_bodyA->getLink(link).m_collider) {
      return collider->getIslandTag();
    }
  }
  return -1;
}

void JointServo::createConstraintRows(btMultiBodyConstraintArray& rows,
                                      btMultiBodyJacobianData& data,
                                      const btContactSolverInfo& info) {
  if (m_numDofsFinalized != m_jacSizeBoth) {
    finalizeMultiDof();  // the Jacobian: 1 at the joint's degree of freedom
  }
  if (m_maxAppliedImpulse == 0) {
    return;
  }
  ARI_CHECK(data.m_fixedBodyId >= 0);  // LeanMultiBodySolver always makes one
  const btMultibodyLink& link = m_bodyA->getLink(m_linkA);
  const btScalar position = m_bodyA->getJointPos(m_linkA);
  const btScalar velocity = m_bodyA->getJointVel(m_linkA);
  // The velocity the servo asks of the joint, as btMultiBodyJointMotor computes it: the position
  // error corrected by kp per step, plus kd of the velocity error, within the rhs clamp.
  const btScalar position_term = m_erp * (m_desiredPosition - position) / info.m_timeStep;
  btScalar target = m_kp * position_term + velocity + m_kd * (m_desiredVelocity - velocity);
  target = btMin(btMax(target, -m_rhsClamp), m_rhsClamp);

  btMultiBodySolverConstraint& row = rows.expandNonInitializing();
  row.m_solverBodyIdA = -1;
  row.m_solverBodyIdB = data.m_fixedBodyId;
  const btVector3 none(0, 0, 0);
  fillMultiBodyConstraint(row, data, jacobianA(0), /*jacOrgB=*/nullptr, none, none, none, none,
                          /*posError=*/0, info, -m_maxAppliedImpulse, m_maxAppliedImpulse,
                          /*angConstraint=*/false, /*relaxation=*/1, /*isFriction=*/false, target);
  row.m_orgConstraint = this;  // joint_efforts() reads the applied impulse back
  row.m_orgDofIndex = 0;
  // The joint axis in the world, for Bullet's constraint-torque bookkeeping.
  const btVector3 axis =
      quatRotate(link.m_cachedWorldTransform.getRotation(), link.m_axes[0].m_topVec);
  row.m_contactNormal1.setZero();
  row.m_contactNormal2.setZero();
  row.m_relpos1CrossNormal = axis;
  row.m_relpos2CrossNormal = -axis;
}

}  // namespace ari_social_sim::physics
