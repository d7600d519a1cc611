#pragma once

#include <array>
#include <string>
#include <vector>

#include "ari_social_sim/navigation/policy.hpp"
#include "ari_social_sim/navigation/policy_observation.hpp"

namespace ari_social_sim::navigation {

/// A trained navigation policy as scripts/train_join_group.py exports it (docs/learning.md,
/// "Deploying a policy"): a feed-forward network over navigation::PolicyObservation, with the
/// observation's normalisation, the action bounds, and the rules it was trained with (control
/// rate, arrival). Read without PyTorch, so that it runs in social_mpc_node and in the batch
/// engine alike.
class MlpPolicy : public Policy {
 public:
  /// The file's format name; a file of another format is refused.
  static constexpr const char* kFormat = "ari_social_sim/mlp_policy/1";

  /// Throws core::ConfigError naming the file and field: another format, layer sizes that do not
  /// chain from the observation's size to kActions, a standard deviation <= 0, bounds not
  /// ordered.
  static MlpPolicy load_file(const std::string& path);

  const std::string& task() const { return task_; }
  const PolicyObservationConfig& observation() const override { return observation_; }
  double control_rate_hz() const override { return control_rate_hz_; }
  double position_tolerance_m() const override { return position_tolerance_m_; }
  double heading_tolerance_rad() const override { return heading_tolerance_rad_; }

  /// The network's output clipped to [-1, 1] and mapped linearly onto [action_low, action_high].
  std::array<double, kActions> act(const float* observation) override;

 private:
  struct Layer {
    int inputs{0};
    int outputs{0};
    std::vector<float> weight;  // outputs x inputs, row-major
    std::vector<float> bias;
    bool tanh{false};
  };

  std::string task_;
  PolicyObservationConfig observation_;
  double control_rate_hz_{20.0};
  double position_tolerance_m_{0.25};
  double heading_tolerance_rad_{0.35};
  std::vector<float> mean_;
  std::vector<float> std_;
  float clip_{10.0f};
  std::array<double, kActions> low_{};
  std::array<double, kActions> high_{};
  std::vector<Layer> layers_;
  std::vector<float> input_;  // act()'s layer inputs and outputs
  std::vector<float> output_;
};

}  // namespace ari_social_sim::navigation
