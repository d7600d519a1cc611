#include "lean_multibody_solver.hpp"

#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

namespace ari_social_sim::physics {
namespace {

bool within_processing_threshold(const btPersistentManifold& manifold,
                                 const btManifoldPoint& point) {
  return point.getDistance() <= manifold.getContactProcessingThreshold();
}

// True when no point Bullet would turn into rows has any friction to apply.
bool is_frictionless(const btPersistentManifold& manifold) {
  for (int i = 0; i < manifold.getNumContacts(); ++i) {
    const btManifoldPoint& point = manifold.getContactPoint(i);
    if (within_processing_threshold(manifold, point) &&
        (point.m_combinedFriction != 0 || point.m_combinedRollingFriction != 0 ||
         point.m_combinedSpinningFriction != 0)) {
      return false;
    }
  }
  return true;
}

}  // namespace

void LeanMultiBodySolver::convertContacts(btPersistentManifold** manifolds, int manifold_count,
                                          const btContactSolverInfo& info) {
  inert_rows_ = -1;
  for (int i = 0; i < manifold_count; ++i) {
    btPersistentManifold* manifold = manifolds[i];
    const bool on_multibody = btMultiBodyLinkCollider::upcast(manifold->getBody0()) != nullptr ||
                              btMultiBodyLinkCollider::upcast(manifold->getBody1()) != nullptr;
    if (!on_multibody) {
      convertContact(manifold, info);
    } else if (is_frictionless(*manifold)) {
      convert_frictionless(manifold, info);
    } else {
      convertMultiBodyContact(manifold, info);
    }
  }
  // JointServo rows hold against the fixed solver body; Bullet makes it only for a static object
  // in contact, so make it here when nothing touches one.
  if (m_fixedBodyId < 0) {
    m_fixedBodyId = m_tmpSolverBodyPool.size();
    // initSolverBody sets every field, as Bullet's getOrInitSolverBody relies on; expand() would
    // first copy an uninitialised btSolverBody into the slot (GCC 12's maybe-uninitialized).
    initSolverBody(&m_tmpSolverBodyPool.expandNonInitializing(), nullptr, info.m_timeStep);
  }
  // No manifolds left: this converts the multibody constraints (joint servos) alone.
  btMultiBodyConstraintSolver::convertContacts(manifolds, 0, info);
}

void LeanMultiBodySolver::convert_frictionless(btPersistentManifold* manifold,
                                               const btContactSolverInfo& info) {
  const btMultiBodyLinkCollider* collider_a = btMultiBodyLinkCollider::upcast(manifold->getBody0());
  const btMultiBodyLinkCollider* collider_b = btMultiBodyLinkCollider::upcast(manifold->getBody1());
  auto* object_a = const_cast<btCollisionObject*>(manifold->getBody0());
  auto* object_b = const_cast<btCollisionObject*>(manifold->getBody1());
  const int solver_body_a =
      collider_a != nullptr ? -1 : getOrInitSolverBody(*object_a, info.m_timeStep);
  const int solver_body_b =
      collider_b != nullptr ? -1 : getOrInitSolverBody(*object_b, info.m_timeStep);

  for (int i = 0; i < manifold->getNumContacts(); ++i) {
    btManifoldPoint& point = manifold->getContactPoint(i);
    if (!within_processing_threshold(*manifold, point)) {
      // As Bullet does: a point out of reach starts cold when it comes back.
      point.m_appliedImpulse = 0;
      point.m_prevRHS = 0;
      continue;
    }
    btMultiBodySolverConstraint& row = m_multiBodyNormalContactConstraints.expandNonInitializing();
    row.m_orgConstraint = nullptr;
    row.m_orgDofIndex = -1;
    row.m_solverBodyIdA = solver_body_a;
    row.m_solverBodyIdB = solver_body_b;
    row.m_multiBodyA = collider_a != nullptr ? collider_a->m_multiBody : nullptr;
    row.m_multiBodyB = collider_b != nullptr ? collider_b->m_multiBody : nullptr;
    if (collider_a != nullptr) {
      row.m_linkA = collider_a->m_link;
    }
    if (collider_b != nullptr) {
      row.m_linkB = collider_b->m_link;
    }
    row.m_originalContactPoint = &point;
    btScalar relaxation = 0;
    setupMultiBodyContactConstraint(row, point.m_normalWorldOnB, point.m_appliedImpulse, point,
                                    info, relaxation, /*isFriction=*/false);
    row.m_frictionIndex = inert_friction_rows(m_multiBodyNormalContactConstraints.size() - 1);
  }
}

int LeanMultiBodySolver::inert_friction_rows(int normal_row) {
  if (inert_rows_ >= 0) {
    return inert_rows_;
  }
  inert_rows_ = m_multiBodyFrictionContactConstraints.size();
  // Two rows: Bullet reads the second direction's row at index + 1.
  for (int i = 0; i < 2; ++i) {
    btMultiBodySolverConstraint& row =
        m_multiBodyFrictionContactConstraints.expandNonInitializing();
    row = btMultiBodySolverConstraint();  // no bodies, no original constraint
    row.m_frictionIndex = normal_row;  // any valid normal row: the impulse limit is 0 x its impulse
    row.m_appliedImpulse = 0;
    row.m_appliedPushImpulse = 0;
    row.m_friction = 0;
    row.m_lowerLimit = 0;
    row.m_upperLimit = 0;
    row.m_rhs = 0;
    row.m_rhsPenetration = 0;
    row.m_cfm = 0;
    row.m_jacDiagABInv = 1;  // the solver divides by it; the row's impulse stays 0
    row.m_originalContactPoint = nullptr;
    row.m_overrideNumSolverIterations = 0;
  }
  return inert_rows_;
}

}  // namespace ari_social_sim::physics
