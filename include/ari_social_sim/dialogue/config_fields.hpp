#pragma once

#include <string>
#include <type_traits>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/yaml_map.hpp"

namespace ari_social_sim::dialogue {

/// Throws core::ConfigError naming `owner` and the first field `visit` lists outside its bounds.
/// Config: a struct with `template <class V> void visit(V&)` calling v(name, field, bounds).
template <class Config>
void check_bounds(const Config& config, const std::string& owner) {
  Config copy = config;
  auto check = [&owner](const char* name, auto& value, const core::Bounds& bounds) {
    if (!bounds.contains(static_cast<double>(value))) {
      throw core::ConfigError(owner + ": " + name + ": expected a number " + bounds.describe() +
                              ", got " + std::to_string(value));
    }
  };
  copy.visit(check);
}

/// Reads every field `visit` lists from `map` (each optional, defaulting to the struct's value),
/// rejects unknown keys, then runs the config's validate(). Errors name the file and field.
template <class Config>
Config read_config(const core::YamlMap& map) {
  Config config;
  auto read = [&map](const char* name, auto& value, const core::Bounds& bounds) {
    value = map.optional<std::decay_t<decltype(value)>>(name, value, bounds);
  };
  config.visit(read);
  map.finish();
  try {
    config.validate();
  } catch (const core::ConfigError& e) {
    throw core::ConfigError(map.source() + ": " + e.what());
  }
  return config;
}

}  // namespace ari_social_sim::dialogue
