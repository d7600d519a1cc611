#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "ari_social_sim/core/config_fields.hpp"
#include "ari_social_sim/core/yaml_map.hpp"
#include "ari_social_sim/perception/perception_config.hpp"

namespace ari_social_sim::perception {

/// How hri_perception_node runs: its private parameters (~config, ~seed, ...), listed once in
/// visit (core/config_fields.hpp; docs/parameters.md is generated from it).
struct PerceptionRunConfig {
  /// What the node stands in for: the whole stack up to persons (kSim), or only the face, body
  /// and voice detectors and the matchers, leaving persons to a real person manager (kDetectors).
  enum class Mode { kSim, kDetectors };
  static constexpr core::Choice<Mode> kModes[] = {{Mode::kSim, "sim"},
                                                  {Mode::kDetectors, "detectors"}};

  Mode mode{Mode::kSim};
  std::string config;
  std::optional<uint64_t> seed;
  std::optional<bool> errors_enabled;
  std::optional<std::string> person_ids;
  std::string world;
  /// The range of `max_rate`, also the batch engine's (scenario::EpisodeConfig).
  static constexpr core::Bounds kMaxRateBounds{0.0, 1000.0, true};
  double max_rate_hz{30.0};
  double id_linger_s{1.0};
  double marker_rate_hz{10.0};
  bool crops{false};
  bool voices{true};
  std::optional<uint64_t> appearance_seed;

  template <class V>
  void visit(V& v) {
    v.choice("mode", mode,
             "sim: detectors and person manager; detectors: no persons, the matchers' candidate "
             "matches",
             kModes);
    v.field("config", config,
            "sensors and error models (config/perception.yaml below); empty: the package's "
            "config/perception.yaml");
    v.field(core::unset_by_minus_one("seed"), seed, "overrides the config's seed when set",
            core::kParameterSeedBounds);
    v.field("errors_enabled", errors_enabled,
            "overrides the config's errors_enabled: false turns every error model off");
    v.field("person_ids", person_ids,
            "overrides the config's persons.id_style: human gives `human<N>`, random "
            "`anonymous_person_<5 letters>`, seeded");
    v.rule("person_ids", !person_ids || PersonConfig::is_id_style(*person_ids),
           PersonConfig::kIdStyles, "'" + person_ids.value_or("") + "'");
    v.field("world", world,
            "a world file whose walls (not furniture) block sound; empty: everything in /map does");
    v.field("max_rate", max_rate_hz, "Hz of sim time; world states closer together are skipped",
            kMaxRateBounds);
    v.field("id_linger", id_linger_s, "s of sim time per-id topics outlive their id",
            core::between(0.0, 60.0));
    v.field("marker_rate", marker_rate_hz, "Hz of ~markers (wall clock)",
            core::Bounds{0.0, 30.0, true});
    v.field("crops", crops,
            "3D mode: cut REP-155's face (cropped, aligned) and body (cropped) images from ARI's "
            "head camera for the tracked faces and bodies; subscribing makes ari_physics_node "
            "render that camera");
    v.field("voices", voices,
            "false: no simulated voices or speech, for speech recognition on the array's audio "
            "(speech:=audio, docs/audio.md) or a real ASR to publish /humans/voices/...");
    v.field(core::unset_by_minus_one("appearance_seed"), appearance_seed,
            "with crops: ari_physics_node's appearance_seed, which sizes the people it draws; "
            "unset: read /ari_physics_node/appearance_seed, 1 (its default) when that is unset",
            core::kParameterSeedBounds);
  }

  /// Throws core::ConfigError naming the field outside what visit allows.
  void validate() const;
  /// Reads every field from a mapping (parameter server or file); unknown keys and out-of-range
  /// values throw core::ConfigError naming the parameter.
  static PerceptionRunConfig from_yaml(const core::YamlMap& map);
};

}  // namespace ari_social_sim::perception
