#pragma once

#include <yaml-cpp/yaml.h>

#include <sstream>
#include <string>

#include "ari_social_sim/core/config_fields.hpp"

namespace ari_social_sim::core {

/// Writes the fields a config's visit lists (config_fields.hpp) into a YAML mapping that
/// read_fields reads back to the same values; unset optional fields and unread mappings are left
/// out.
class FieldWriter {
 public:
  YAML::Node node{YAML::NodeType::Map};

  template <class T>
  void field(const Key& key, const T& value, const char* /*meaning*/, const Bounds& = {}) {
    if constexpr (IsOptional<T>::value) {
      if (value) {
        write(key.name, *value);
      }
    } else {
      write(key.name, value);
    }
  }

  template <class E, class Choices>
  void choice(const Key& key, E value, const char* /*meaning*/, const Choices& choices) {
    node[key.name] = choice_name(value, choices);
  }

  template <class S>
  void section(const Key& key, S& section, const char* /*meaning*/) {
    FieldWriter nested;
    section.visit(nested);
    node[key.name] = nested.node;
  }

  void rule(const std::string&, bool, const std::string&, const std::string&) const {}

 private:
  template <class T>
  void write(const std::string& key, const T& value) {
    if constexpr (std::is_floating_point_v<T>) {
      // Full precision, so that reading back gives the same double.
      std::ostringstream text;
      text.precision(17);
      text << value;
      node[key] = text.str();
    } else if constexpr (!std::is_same_v<T, YamlMap>) {
      node[key] = value;
    }
  }
};

/// `config` as YAML text (FieldWriter).
template <class Config>
std::string write_fields(const Config& config) {
  Config copy = config;
  FieldWriter writer;
  copy.visit(writer);
  YAML::Emitter out;
  out << writer.node;
  return out.c_str();
}

}  // namespace ari_social_sim::core
