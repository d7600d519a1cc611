#pragma once

#include <optional>
#include <string>
#include <vector>

#include "ari_social_sim/core/config_fields.hpp"
#include "ari_social_sim/core/number_text.hpp"

namespace ari_social_sim::core {

/// One documented parameter: where it sits (section names, then the field's), its type, default,
/// allowed range and meaning, as docs/parameters.md shows them.
struct ParameterRow {
  std::vector<std::string> path;
  std::string type;
  std::string default_value;
  std::string range;
  std::string meaning;
};

/// A rule across fields (config_fields.hpp), as docs/parameters.md lists it below the table.
struct ParameterRule {
  std::vector<std::string> path;
  std::string expectation;
};

/// Collects what a config's visit declares (config_fields.hpp) for the documentation: one row per
/// field and section, in the order visit lists them, the defaults being the visited values.
class ParameterTable {
 public:
  ParameterTable() = default;

  template <class T>
  void field(const Key& key, const T& value, const char* meaning, const Bounds& bounds = {}) {
    std::string range = bounds.describe();
    if constexpr (IsVector<typename Unoptional<T>::type>::value) {
      range = range.empty() ? "" : "each " + range;
    }
    if (key.minus_one_unsets) {
      range += (range.empty() ? "" : "; ") + std::string("-1: unset");
    }
    add(key, type_name<T>(), key.required ? "required" : value_text(value), range, meaning);
  }

  template <class E, class Choices>
  void choice(const Key& key, E value, const char* meaning, const Choices& choices) {
    add(key, "string",
        key.required ? "required" : "`" + std::string(choice_name(value, choices)) + "`",
        choice_names(choices), meaning);
  }

  template <class S>
  void section(const Key& key, S& section, const char* meaning) {
    add(key, "mapping", "", "", meaning);
    add_nested(key.name, section);
  }

  /// An optional section: unset by default, its fields' defaults those of a default S.
  template <class S>
  void section(const Key& key, std::optional<S>& /*section*/, const char* meaning) {
    add(key, "mapping", "unset", "", meaning);
    S defaults{};
    add_nested(key.name, defaults);
  }

  /// A list of mappings: one row for the list, then its items' fields as `key[].field`.
  template <class S>
  void list(const Key& key, std::vector<S>& /*items*/, const char* meaning, size_t max_items) {
    add(key, "list of mappings", key.required ? "required" : "`[]`",
        "at most " + std::to_string(max_items) + " items", meaning);
    S defaults{};
    add_nested(key.name + "[]", defaults);
  }

  void rule(const std::string& name, bool /*holds*/, const std::string& expectation,
            const std::string& /*got*/) {
    rules_.push_back({path_of(name), expectation});
  }

  const std::vector<ParameterRow>& rows() const { return rows_; }
  const std::vector<ParameterRule>& rules() const { return rules_; }

  /// A Markdown table (parameter, type, default, range, meaning) and the rules below it. Each
  /// parameter is written `prefix` + its path joined by `separator`: `~mpc/step` for a node's
  /// private parameters, `mpc.step` for a file's keys.
  std::string markdown(const std::string& prefix, const std::string& separator) const;

 private:
  template <class T>
  static std::string value_text(const T& value) {
    if constexpr (IsOptional<T>::value) {
      return value ? value_text(*value) : "unset";
    } else if constexpr (std::is_same_v<T, YamlMap>) {
      return "";
    } else if constexpr (IsVector<T>::value) {
      std::string items;
      for (const auto& item : value) {
        items += (items.empty() ? "" : ", ") + item_text(item);
      }
      return "`[" + items + "]`";
    } else {
      return "`" + item_text(value) + "`";
    }
  }

  template <class S>
  void add_nested(const std::string& name, S& section) {
    ParameterTable nested;
    nested.prefix_ = path_of(name);
    section.visit(nested);
    rows_.insert(rows_.end(), nested.rows_.begin(), nested.rows_.end());
    rules_.insert(rules_.end(), nested.rules_.begin(), nested.rules_.end());
  }

  template <class T>
  static std::string item_text(const T& value) {
    if constexpr (std::is_same_v<T, Eigen::Vector2d>) {
      return "[" + number_text(value.x()) + ", " + number_text(value.y()) + "]";
    } else if constexpr (std::is_same_v<T, bool>) {
      return value ? "true" : "false";
    } else if constexpr (std::is_same_v<T, std::string>) {
      return value.empty() ? "\"\"" : value;
    } else {
      return number_text(static_cast<double>(value));
    }
  }

  void add(const Key& key, std::string type, std::string default_value, std::string range,
           const char* meaning);
  std::vector<std::string> path_of(const std::string& name) const;

  std::vector<std::string> prefix_;
  std::vector<ParameterRow> rows_;
  std::vector<ParameterRule> rules_;
};

/// The table of a Config at its defaults.
template <class Config>
ParameterTable parameter_table(Config config = {}) {
  ParameterTable table;
  config.visit(table);
  return table;
}

}  // namespace ari_social_sim::core
