#pragma once

#include <string>

#include "ari_social_sim/core/config_fields.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/number_text.hpp"

namespace ari_social_sim::core {

/// Checks a config built in code against what its visit declares (config_fields.hpp): numbers
/// finite and within their bounds, choices among their values, required strings given, rules
/// holding. Throws ConfigError naming the struct, the field path, the expectation and the value:
/// `PerceptionConfig: body_errors.miss_rate: expected a number [0, 1], got 1.5`; without an owner
/// the message starts at the field.
class FieldChecker {
 public:
  FieldChecker(std::string owner, std::string path)
      : owner_(std::move(owner)), path_(std::move(path)) {}

  template <class T>
  void field(const Key& key, const T& value, const char* /*meaning*/, const Bounds& bounds = {}) {
    if constexpr (IsOptional<T>::value) {
      if (value) {
        check(key.name, *value, bounds);
      }
    } else {
      check(key.name, value, bounds);
      if constexpr (std::is_same_v<T, std::string>) {
        if (key.required && value.empty()) {
          rule(key.name, false, "a value (the field is required)", "''");
        }
      }
    }
  }

  template <class E, class Choices>
  void choice(const Key& key, E value, const char* /*meaning*/, const Choices& choices) {
    const bool named = *choice_name(value, choices) != '\0';
    rule(key.name, named, choice_names(choices),
         "the value " + std::to_string(static_cast<long long>(value)));
  }

  template <class S>
  void section(const Key& key, S& section, const char* /*meaning*/) {
    FieldChecker nested(owner_, path_of(key.name));
    section.visit(nested);
  }

  void rule(const std::string& name, bool holds, const std::string& expectation,
            const std::string& got) const {
    if (!holds) {
      throw ConfigError((owner_.empty() ? "" : owner_ + ": ") + path_of(name) + ": expected " +
                        expectation + ", got " + got);
    }
  }

 private:
  template <class T>
  void check(const std::string& name, const T& value, const Bounds& bounds) const {
    const std::string range = bounds.describe();
    if constexpr (kIsConfigNumber<T>) {
      rule(name, within(value, bounds), type_phrase<T>() + (range.empty() ? "" : " " + range),
           number_text(static_cast<double>(value)));
    } else if constexpr (IsVector<T>::value) {
      if constexpr (kIsConfigNumber<typename T::value_type>) {
        std::string items;
        bool all_within = true;
        for (const auto item : value) {
          all_within = all_within && within(item, bounds);
          items += (items.empty() ? "" : ", ") + number_text(static_cast<double>(item));
        }
        rule(name, all_within, type_phrase<T>() + (range.empty() ? "" : ", each " + range),
             "[" + items + "]");
      }
    }
  }

  std::string path_of(const std::string& name) const {
    return path_.empty() ? name : path_ + "." + name;
  }

  std::string owner_;
  std::string path_;
};

/// Throws ConfigError unless `config` is what its visit allows; `owner` names the struct in the
/// message (may be empty). What every config's validate() calls.
template <class Config>
void check_fields(const Config& config, const std::string& owner) {
  // visit is one template for reading and checking, so it takes the struct by non-const reference.
  Config copy = config;
  FieldChecker checker(owner, "");
  copy.visit(checker);
}

/// `config` after its validate(), for constructors that check their config before their members
/// use it: `config_(core::validated(config))`.
template <class Config>
const Config& validated(const Config& config) {
  config.validate();
  return config;
}

}  // namespace ari_social_sim::core
