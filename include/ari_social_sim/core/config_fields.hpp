#pragma once

#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "ari_social_sim/core/bounds.hpp"
#include "ari_social_sim/core/error.hpp"

// The one way configurations are declared. A config struct lists each field once, in
//
//   template <class V>
//   void visit(V& v) {
//     v.field("step", step_s, "sim seconds per step", core::Bounds{0.0, 1.0, true});
//     v.field(core::required("scenario"), scenario, "the scenario file");
//     v.choice("solver", solver, "the optimiser", kSolverNames);
//     v.section("weights", weights, "weight of each cost term");
//     v.rule("max_patience", min_patience <= max_patience, "an integer >= min_patience", ...);
//   }
//
// with the field's name in files and parameters, its meaning and its bounds; the member
// initialisers are the defaults. Four visitors walk that list: core::read_fields (files and
// parameters, config_reader.hpp), core::check_fields (structs built in code: every validate(),
// config_check.hpp), core::write_fields (YAML text, config_writer.hpp) and core::ParameterTable
// (docs/parameters.md, parameter_table.hpp). So a bound or default is written once, and the docs
// cannot disagree with the code.
//
//   v.field(key, member, meaning[, bounds])  a value; a std::optional member may stay unset;
//                                            core::unset_by_minus_one(key) also reads -1 as unset
//   v.choice(key, member, meaning, choices)  an enum, spelled in files by the names of `choices`
//   v.section(key, member, meaning)          a nested struct (its own visit): a nested mapping;
//                                            a std::optional member is set only when given
//   v.list(key, member, meaning, max_items)  a std::vector of structs (each its own visit): a
//                                            list of mappings, at most max_items of them
//   v.rule(name, holds, expectation, got)    a check across fields, listed after the fields it
//   reads
//
// Field types: bool, int, unsigned, int64_t (read as int), uint64_t (read as unsigned), double,
// std::string, Eigen::Vector2d (a point `[x, y]`, bounds apply to each coordinate), std::vector of
// double, unsigned, std::string or Eigen::Vector2d, std::optional of any of these, and
// std::optional<YamlMap>: a mapping handed unread to another reader. Numbers checked in code must
// be finite and within their bounds, as YamlMap requires of numbers read from files.

namespace ari_social_sim::core {

// Only named here (a mapping handed unread to another reader); config_reader.hpp reads it.
class YamlMap;

/// A field's name, and whether files must give it (`core::required("mode")`); a field that is not
/// required keeps its default when absent.
struct Key {
  Key(const char* key_name) : name(key_name) {}
  Key(std::string key_name) : name(std::move(key_name)) {}

  std::string name;
  bool required{false};
  // A std::optional<uint64_t> field (a seed) that -1 leaves unset, see unset_by_minus_one.
  bool minus_one_unsets{false};
};

inline Key required(std::string name) {
  Key key(std::move(name));
  key.required = true;
  return key;
}

/// The key of a std::optional<uint64_t> field, a seed, that files and parameters may also set to
/// -1, meaning unset: a launch file's `seed:=-1` default passes "the file's seed" on to a node
/// this way. The reader is the one place -1 becomes unset; in code the field is the optional.
inline Key unset_by_minus_one(std::string name) {
  Key key(std::move(name));
  key.minus_one_unsets = true;
  return key;
}

/// Seeds that nodes take as parameters: a ROS integer parameter is 32-bit and signed.
inline constexpr Bounds kParameterSeedBounds{0.0, 2147483647.0, false};

/// One value of an enumerated field and how files spell it.
template <class E>
struct Choice {
  E value;
  const char* name;
};

/// "a, b or c": the names of `choices` as messages and docs list them.
template <class Choices>
std::string choice_names(const Choices& choices) {
  std::vector<std::string> names;
  for (const auto& choice : choices) {
    names.emplace_back(choice.name);
  }
  std::string text;
  for (size_t i = 0; i < names.size(); ++i) {
    text += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
  }
  return text;
}

/// The name of `value` among `choices`; "" when it has none.
template <class E, class Choices>
const char* choice_name(E value, const Choices& choices) {
  for (const auto& choice : choices) {
    if (choice.value == value) {
      return choice.name;
    }
  }
  return "";
}

/// True when `text` names one of `choices`.
template <class Choices>
bool names_a_choice(const std::string& text, const Choices& choices) {
  for (const auto& choice : choices) {
    if (text == choice.name) {
      return true;
    }
  }
  return false;
}

/// The value `text` names among `choices`. Throws ConfigError naming `field` and the choices.
template <class Choices>
auto parse_choice(const std::string& text, const Choices& choices, const std::string& field) {
  for (const auto& choice : choices) {
    if (text == choice.name) {
      return choice.value;
    }
  }
  throw ConfigError(field + ": expected " + choice_names(choices) + ", got '" + text + "'");
}

template <class T>
struct IsOptional : std::false_type {};
template <class T>
struct IsOptional<std::optional<T>> : std::true_type {};

/// T, or the T of a std::optional<T>.
template <class T>
struct Unoptional {
  using type = T;
};
template <class T>
struct Unoptional<std::optional<T>> {
  using type = T;
};

template <class T>
struct IsVector : std::false_type {};
template <class T>
struct IsVector<std::vector<T>> : std::true_type {};

template <class T>
constexpr bool kIsConfigNumber = std::is_arithmetic_v<T> && !std::is_same_v<T, bool>;

/// What a value of type T is called in messages and docs: "number", "integer", "list of numbers".
template <class T>
std::string type_name() {
  if constexpr (IsOptional<T>::value) {
    return type_name<typename T::value_type>();
  } else if constexpr (std::is_same_v<T, std::vector<Eigen::Vector2d>>) {
    return "list of points [x, y]";
  } else if constexpr (IsVector<T>::value) {
    return "list of " + type_name<typename T::value_type>() + "s";
  } else if constexpr (std::is_same_v<T, YamlMap>) {
    return "mapping";
  } else if constexpr (std::is_same_v<T, Eigen::Vector2d>) {
    return "point [x, y]";
  } else if constexpr (std::is_same_v<T, bool>) {
    return "bool";
  } else if constexpr (std::is_same_v<T, std::string>) {
    return "string";
  } else if constexpr (std::is_floating_point_v<T>) {
    return "number";
  } else if constexpr (std::is_unsigned_v<T>) {
    return "non-negative integer";
  } else {
    static_assert(std::is_integral_v<T>, "a config field of a type config_fields.hpp lists");
    return "integer";
  }
}

/// "a number", "an integer": type_name with its article, as messages expect it.
template <class T>
std::string type_phrase() {
  const std::string name = type_name<T>();
  return (name[0] == 'i' ? "an " : "a ") + name;
}

/// True when a number read or built for a field of type T lies within `bounds` (and, for floating
/// point, is finite); for a point, when both coordinates do.
template <class T>
bool within(const T& value, const Bounds& bounds) {
  if constexpr (std::is_same_v<T, Eigen::Vector2d>) {
    return within(value.x(), bounds) && within(value.y(), bounds);
  } else {
    if constexpr (std::is_floating_point_v<T>) {
      if (!std::isfinite(value)) {
        return false;
      }
    }
    return bounds.contains(static_cast<double>(value));
  }
}

}  // namespace ari_social_sim::core
