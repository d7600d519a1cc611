#include "ari_social_sim/navigation/mppi_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ari_social_sim::navigation {
namespace {

// Correlation of the noise from one step to the next, so samples are smooth swerves rather than
// jitter the smoothness term would reject anyway.
constexpr double kNoiseCorrelation = 0.8;

}  // namespace

MppiSolver::MppiSolver(const MpcConfig& config)
    : config_(config),
      rng_(config.seed),
      samples_(static_cast<size_t>(config.mppi_samples),
               Eigen::VectorXd::Zero(config.control_count())),
      costs_(static_cast<size_t>(config.mppi_samples)) {}

double MppiSolver::minimise(TrajectoryCost& cost, const ControlBounds& bounds,
                            Eigen::VectorXd& controls) {
  const double sigma[3] = {config_.mppi_noise_linear, config_.mppi_noise_angular,
                           config_.mppi_noise_pan};
  const double innovation = std::sqrt(1.0 - kNoiseCorrelation * kNoiseCorrelation);
  const int steps = config_.horizon_steps;
  Eigen::VectorXd best = bounds.clamp(controls);
  double best_cost = cost.evaluate(best);
  Eigen::VectorXd nominal = best;
  for (int iteration = 0; iteration < config_.mppi_iterations; ++iteration) {
    // The weights are taken against the cheapest sample of this round, not the best so far: when
    // every sample is far dearer than the start, weights against the start would all underflow
    // to 0 and the average be 0 / 0.
    double min_cost = std::numeric_limits<double>::infinity();
    for (size_t k = 0; k < samples_.size(); ++k) {
      Eigen::VectorXd& sample = samples_[k];
      double noise[3] = {0.0, 0.0, 0.0};
      for (int t = 0; t < steps; ++t) {
        for (int c = 0; c < kControlsPerStep; ++c) {
          const double fresh = rng_.normal(0.0, sigma[c]);
          noise[c] = t == 0 ? fresh : kNoiseCorrelation * noise[c] + innovation * fresh;
          sample[kControlsPerStep * t + c] = nominal[kControlsPerStep * t + c] + noise[c];
        }
      }
      sample = bounds.clamp(sample);
      costs_[k] = cost.evaluate(sample);
      min_cost = std::min(min_cost, costs_[k]);
      if (costs_[k] < best_cost) {
        best_cost = costs_[k];
        best = sample;
      }
    }
    Eigen::VectorXd weighted = Eigen::VectorXd::Zero(nominal.size());
    double weight_sum = 0.0;
    for (size_t k = 0; k < samples_.size(); ++k) {
      const double w = std::exp(-(costs_[k] - min_cost) / config_.mppi_temperature);
      weighted += w * samples_[k];
      weight_sum += w;
    }
    nominal = weighted / weight_sum;
    const double nominal_cost = cost.evaluate(nominal);
    if (nominal_cost < best_cost) {
      best_cost = nominal_cost;
      best = nominal;
    }
  }
  controls = best;
  return best_cost;
}

}  // namespace ari_social_sim::navigation
