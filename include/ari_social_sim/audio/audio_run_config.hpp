#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "ari_social_sim/audio/room_acoustics.hpp"
#include "ari_social_sim/core/config_fields.hpp"
#include "ari_social_sim/core/yaml_map.hpp"

namespace ari_social_sim::audio {

/// How audio_node runs: its private parameters, listed once in visit (config_fields.hpp;
/// docs/parameters.md is generated from it).
struct AudioRunConfig {
  std::string scene;
  std::optional<uint64_t> seed;
  RoomSettings room;

  template <class V>
  void visit(V& v) {
    v.field("scene", scene,
            "the scene or scenario file world_node plays (its walls reflect, its seed draws the "
            "voices); empty: the package's scenes/waiting_room.yaml");
    v.field(core::unset_by_minus_one("seed"), seed, "overrides the scene's seed when set",
            core::kParameterSeedBounds);
    room.visit(v);
  }

  /// Throws core::ConfigError naming the field outside what visit allows.
  void validate() const;
  /// Reads every field from a mapping (parameter server or file); unknown keys and out-of-range
  /// values throw core::ConfigError naming the parameter.
  static AudioRunConfig from_yaml(const core::YamlMap& map);
};

}  // namespace ari_social_sim::audio
