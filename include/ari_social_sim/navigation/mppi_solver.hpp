#pragma once

#include "ari_social_sim/core/rng.hpp"
#include "ari_social_sim/navigation/mpc_solver.hpp"

namespace ari_social_sim::navigation {

/// Model predictive path integral control (Williams et al. 2017), the sampling alternative:
/// `samples` perturbations of the current sequence (Gaussian noise correlated along the horizon,
/// clamped to the bounds) are rolled out and averaged with weights exp(-(J - J_min) / lambda), for
/// `iterations` rounds. Keeps the best of the average and the best sample. Seeded: the same seed
/// and inputs give the same controls.
class MppiSolver : public MpcSolver {
 public:
  explicit MppiSolver(const MpcConfig& config);

  double minimise(TrajectoryCost& cost, const ControlBounds& bounds,
                  Eigen::VectorXd& controls) override;

 private:
  MpcConfig config_;
  core::Rng rng_;
  std::vector<Eigen::VectorXd> samples_;
  std::vector<double> costs_;
};

}  // namespace ari_social_sim::navigation
