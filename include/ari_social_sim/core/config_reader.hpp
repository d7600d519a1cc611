#pragma once

#include <optional>
#include <string>
#include <vector>

#include "ari_social_sim/core/config_fields.hpp"
#include "ari_social_sim/core/yaml_map.hpp"

namespace ari_social_sim::core {

/// Reads the fields a config's visit lists (config_fields.hpp) from a mapping: each present key
/// replaces the default, sections recurse into nested mappings, and rules are checked once the
/// fields before them are read. Errors are YamlMap's: `source: path.key: expected ..., got ...`.
class FieldReader {
 public:
  explicit FieldReader(const YamlMap& map) : map_(map) {}

  template <class T>
  void field(const Key& key, T& value, const char* /*meaning*/, const Bounds& bounds = {}) {
    if (key.required || map_.has(key.name)) {
      if constexpr (std::is_same_v<T, std::optional<uint64_t>>) {
        value = read_seed(key, bounds);
      } else if constexpr (IsOptional<T>::value) {
        value = read<typename T::value_type>(key.name, bounds);
      } else {
        value = read<T>(key.name, bounds);
      }
    }
  }

  template <class E, class Choices>
  void choice(const Key& key, E& value, const char* /*meaning*/, const Choices& choices) {
    if (key.required || map_.has(key.name)) {
      const std::string text = map_.required<std::string>(key.name);
      for (const auto& choice : choices) {
        if (text == choice.name) {
          value = choice.value;
          return;
        }
      }
      map_.fail(key.name, choice_names(choices), "'" + text + "'");
    }
  }

  template <class S>
  void section(const Key& key, S& section, const char* /*meaning*/) {
    if (key.required || map_.has(key.name)) {
      read_section(map_.map(key.name), section);
    }
  }

  template <class S>
  void section(const Key& key, std::optional<S>& section, const char* /*meaning*/) {
    if (key.required || map_.has(key.name)) {
      read_section(map_.map(key.name), section.emplace());
    }
  }

  template <class S>
  void list(const Key& key, std::vector<S>& items, const char* /*meaning*/, size_t max_items) {
    if (!key.required && !map_.has(key.name)) {
      return;
    }
    const std::vector<YamlMap> entries = map_.list(key.name);
    if (entries.size() > max_items) {
      map_.fail(key.name, "at most " + std::to_string(max_items) + " " + key.name,
                std::to_string(entries.size()));
    }
    items.assign(entries.size(), S{});
    for (size_t i = 0; i < entries.size(); ++i) {
      read_section(entries[i], items[i]);
    }
  }

  void rule(const std::string& name, bool holds, const std::string& expectation,
            const std::string& got) const {
    if (!holds) {
      map_.fail(name, expectation, got);
    }
  }

 private:
  template <class T>
  T read(const std::string& key, const Bounds& bounds) const {
    if constexpr (std::is_same_v<T, YamlMap>) {
      return map_.map(key);
    } else if constexpr (std::is_same_v<T, int64_t>) {
      return map_.required<int>(key, bounds);
    } else if constexpr (std::is_same_v<T, uint64_t>) {
      return map_.required<unsigned>(key, bounds);
    } else {
      return map_.required<T>(key, bounds);
    }
  }

  // An optional seed: a non-negative integer within `bounds`, or -1 (unset) for an
  // unset_by_minus_one key.
  std::optional<uint64_t> read_seed(const Key& key, const Bounds& bounds) const {
    if (!key.minus_one_unsets) {
      return read<uint64_t>(key.name, bounds);
    }
    const int64_t given = read<int64_t>(key.name, Bounds{-1.0, bounds.max, false});
    if (given == -1) {
      return std::nullopt;
    }
    return read<uint64_t>(key.name, bounds);
  }

  template <class S>
  static void read_section(const YamlMap& nested, S& section) {
    FieldReader reader(nested);
    section.visit(reader);
    nested.finish();
  }

  const YamlMap& map_;
};

/// Reads every field `config.visit` lists from `map` over the values `config` holds, then rejects
/// the keys of `map` that no field names (YamlMap::finish).
template <class Config>
void read_fields(const YamlMap& map, Config& config) {
  FieldReader reader(map);
  config.visit(reader);
  map.finish();
}

/// A Config with its defaults, overridden by `map` (read_fields).
template <class Config>
Config read_fields(const YamlMap& map) {
  Config config;
  read_fields(map, config);
  return config;
}

}  // namespace ari_social_sim::core
