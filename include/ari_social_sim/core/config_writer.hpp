#pragma once

#include <yaml-cpp/yaml.h>

#include <optional>
#include <sstream>
#include <string>
#include <vector>

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
    node[key.name] = written(section);
  }

  template <class S>
  void section(const Key& key, std::optional<S>& section, const char* /*meaning*/) {
    if (section) {
      node[key.name] = written(*section);
    }
  }

  template <class S>
  void list(const Key& key, std::vector<S>& items, const char* /*meaning*/, size_t /*max_items*/) {
    YAML::Node sequence(YAML::NodeType::Sequence);
    for (S& item : items) {
      sequence.push_back(written(item));
    }
    node[key.name] = sequence;
  }

  void rule(const std::string&, bool, const std::string&, const std::string&) const {}

 private:
  template <class S>
  static YAML::Node written(S& section) {
    FieldWriter nested;
    section.visit(nested);
    return nested.node;
  }

  // Full precision, so that reading back gives the same double.
  static std::string exact_text(double value) {
    std::ostringstream text;
    text.precision(17);
    text << value;
    return text.str();
  }

  static YAML::Node point_node(const Eigen::Vector2d& point) {
    YAML::Node xy(YAML::NodeType::Sequence);
    xy.SetStyle(YAML::EmitterStyle::Flow);
    xy.push_back(exact_text(point.x()));
    xy.push_back(exact_text(point.y()));
    return xy;
  }

  template <class T>
  void write(const std::string& key, const T& value) {
    if constexpr (std::is_floating_point_v<T>) {
      node[key] = exact_text(value);
    } else if constexpr (std::is_same_v<T, Eigen::Vector2d>) {
      node[key] = point_node(value);
    } else if constexpr (std::is_same_v<T, std::vector<Eigen::Vector2d>>) {
      YAML::Node points(YAML::NodeType::Sequence);
      for (const Eigen::Vector2d& point : value) {
        points.push_back(point_node(point));
      }
      node[key] = points;
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
