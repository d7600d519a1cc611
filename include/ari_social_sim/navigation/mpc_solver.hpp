#pragma once

#include <Eigen/Core>
#include <memory>

#include "ari_social_sim/navigation/navigation_config.hpp"
#include "ari_social_sim/navigation/trajectory_cost.hpp"

namespace ari_social_sim::navigation {

/// Box bounds on the flat control vector (3 N values).
struct ControlBounds {
  Eigen::VectorXd lower;
  Eigen::VectorXd upper;

  /// v in [min, max linear], |w| <= max angular, |pan rate| <= ARI's head speed, every step.
  static ControlBounds of(const MpcConfig& config);
  Eigen::VectorXd clamp(const Eigen::VectorXd& controls) const {
    return controls.cwiseMax(lower).cwiseMin(upper);
  }
};

/// An optimiser of the MPC objective within box bounds. `controls` holds the start point on entry
/// and the best point found on return; returns its cost. Never throws: numeric failure keeps the
/// start point (docs/navigation.md compares the implementations).
class MpcSolver {
 public:
  virtual ~MpcSolver() = default;
  virtual double minimise(TrajectoryCost& cost, const ControlBounds& bounds,
                          Eigen::VectorXd& controls) = 0;
};

/// The solver `config.solver` names.
std::unique_ptr<MpcSolver> make_solver(const MpcConfig& config);

}  // namespace ari_social_sim::navigation
