#include "ari_social_sim/navigation/mlp_policy.hpp"

#include <algorithm>
#include <cmath>

#include "ari_social_sim/core/config_reader.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/yaml_map.hpp"

namespace ari_social_sim::navigation {
namespace {

std::vector<float> floats(const core::YamlMap& map, const std::string& key, size_t size) {
  const auto values = map.required<std::vector<double>>(key);
  if (values.size() != size) {
    map.fail(key, std::to_string(size) + " numbers", std::to_string(values.size()) + " numbers");
  }
  return {values.begin(), values.end()};
}

}  // namespace

MlpPolicy MlpPolicy::load_file(const std::string& path) {
  const core::YamlMap file = core::YamlMap::load_file(path);
  MlpPolicy policy;
  const auto format = file.required<std::string>("format");
  if (format != kFormat) {
    file.fail("format", kFormat, format);
  }
  policy.task_ = file.required<std::string>("task");
  core::read_fields(file.map("observation"), policy.observation_);
  policy.control_rate_hz_ = file.required<double>("control_rate", core::between(1.0, 100.0));
  const core::YamlMap arrival = file.map("arrival");
  policy.position_tolerance_m_ =
      arrival.required<double>("position_tolerance", core::Bounds{0.0, 2.0, true});
  policy.heading_tolerance_rad_ =
      arrival.required<double>("heading_tolerance", core::Bounds{0.0, 3.1416, true});
  arrival.finish();

  const size_t size = static_cast<size_t>(PolicyObservation(policy.observation_).size());
  policy.mean_ = floats(file, "observation_mean", size);
  policy.std_ = floats(file, "observation_std", size);
  if (std::any_of(policy.std_.begin(), policy.std_.end(), [](float s) { return !(s > 0.0f); })) {
    file.fail("observation_std", "numbers > 0", "a number <= 0");
  }
  policy.clip_ = static_cast<float>(file.required<double>("observation_clip", core::positive()));
  const std::vector<float> low = floats(file, "action_low", kActions);
  const std::vector<float> high = floats(file, "action_high", kActions);
  for (int i = 0; i < kActions; ++i) {
    if (!(low[i] < high[i])) {
      file.fail("action_high", "each above action_low", std::to_string(high[i]));
    }
    policy.low_[i] = low[i];
    policy.high_[i] = high[i];
  }

  int inputs = static_cast<int>(size);
  const std::vector<core::YamlMap> layers = file.list("layers");
  if (layers.empty()) {
    file.fail("layers", "at least one layer", "none");
  }
  for (const core::YamlMap& entry : layers) {
    Layer layer;
    layer.inputs = entry.required<int>("inputs", core::between(1, 1 << 16));
    if (layer.inputs != inputs) {
      entry.fail("inputs", std::to_string(inputs) + " (the previous layer's outputs)",
                 std::to_string(layer.inputs));
    }
    layer.outputs = entry.required<int>("outputs", core::between(1, 1 << 16));
    const auto activation = entry.required<std::string>("activation");
    if (activation != "tanh" && activation != "none") {
      entry.fail("activation", "tanh or none", activation);
    }
    layer.tanh = activation == "tanh";
    layer.weight = floats(entry, "weight", static_cast<size_t>(layer.inputs) * layer.outputs);
    layer.bias = floats(entry, "bias", layer.outputs);
    entry.finish();
    inputs = layer.outputs;
    policy.layers_.push_back(std::move(layer));
  }
  if (inputs != kActions) {
    file.fail("layers", "a last layer of " + std::to_string(kActions) + " outputs",
              std::to_string(inputs) + " outputs");
  }
  file.finish();
  return policy;
}

std::array<double, MlpPolicy::kActions> MlpPolicy::act(const float* observation) {
  // The buffers are members, so a control cycle allocates nothing.
  std::vector<float>& input = input_;
  std::vector<float>& output = output_;
  input.resize(mean_.size());
  for (size_t i = 0; i < input.size(); ++i) {
    input[i] = std::clamp((observation[i] - mean_[i]) / std_[i], -clip_, clip_);
  }
  for (const Layer& layer : layers_) {
    output.assign(layer.bias.begin(), layer.bias.end());
    for (int o = 0; o < layer.outputs; ++o) {
      const float* row = layer.weight.data() + static_cast<size_t>(o) * layer.inputs;
      float sum = 0.0f;
      for (int i = 0; i < layer.inputs; ++i) {
        sum += row[i] * input[i];
      }
      output[o] += sum;
      if (layer.tanh) {
        output[o] = std::tanh(output[o]);
      }
    }
    input.swap(output);
  }
  std::array<double, kActions> action{};
  for (int i = 0; i < kActions; ++i) {
    const double unit = std::clamp(static_cast<double>(input[i]), -1.0, 1.0);
    action[i] = low_[i] + (unit + 1.0) * 0.5 * (high_[i] - low_[i]);
  }
  return action;
}

}  // namespace ari_social_sim::navigation
