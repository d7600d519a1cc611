#pragma once

#include <BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h>

namespace ari_social_sim::physics {

/// Bullet's multibody solver without rows that can never carry an impulse.
///
/// Setting up a row costs a Jacobian and the multibody's response to it over the whole tree
/// (btMultiBody::calcAccelerationDeltasMultiDof), most of a physics step. Two kinds of row are
/// left out, and the result is the same as Bullet's to the last bit:
/// - Friction rows of frictionless contacts. Bullet gives every contact two, and with a friction
///   coefficient of 0 (ARI's casters and shell, docs/physics.md) they are clamped to zero impulse
///   on every iteration. A manifold whose points all have zero friction, rolling and spinning
///   friction gets its normal rows only; their friction index points at one pair of inert rows
///   (no bodies, no impulse), which is all Bullet's write-back reads from them.
/// - The second side of a joint servo (JointServo), which is held against the fixed solver body
///   this solver always provides instead of against the multibody with an all-zero Jacobian.
/// Every other manifold, and every other constraint, goes through Bullet's own conversion in the
/// same order.
class LeanMultiBodySolver : public btMultiBodyConstraintSolver {
 protected:
  void convertContacts(btPersistentManifold** manifolds, int manifold_count,
                       const btContactSolverInfo& info) override;

 private:
  void convert_frictionless(btPersistentManifold* manifold, const btContactSolverInfo& info);
  /// Index of the pair of inert friction rows, made on first use in each solve.
  int inert_friction_rows(int normal_row);

  int inert_rows_{-1};
};

}  // namespace ari_social_sim::physics
