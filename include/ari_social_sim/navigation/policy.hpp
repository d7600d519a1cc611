#pragma once

#include <array>

#include "ari_social_sim/navigation/policy_observation.hpp"

namespace ari_social_sim::navigation {

/// A navigation policy that PolicyController runs: what it is shown, how often it acts, when it
/// has arrived, and its command for an observation. A trained network (MlpPolicy), or a learner
/// outside the engine (learning::ExternalPolicy).
class Policy {
 public:
  static constexpr int kActions = 3;  // linear m/s, angular rad/s, head pan rad

  virtual ~Policy() = default;
  virtual const PolicyObservationConfig& observation() const = 0;
  virtual double control_rate_hz() const = 0;
  virtual double position_tolerance_m() const = 0;
  virtual double heading_tolerance_rad() const = 0;
  /// The command for one observation (PolicyObservation(observation()).size() values).
  virtual std::array<double, kActions> act(const float* observation) = 0;
};

}  // namespace ari_social_sim::navigation
