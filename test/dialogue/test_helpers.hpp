#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "ari_social_sim/core/error.hpp"

namespace ari_social_sim::dialogue::testing {

/// Expects `body` to throw core::ConfigError whose message contains every fragment.
template <class F>
void expect_config_error(F body, const std::vector<std::string>& fragments) {
  try {
    body();
    ADD_FAILURE() << "no ConfigError thrown";
  } catch (const core::ConfigError& e) {
    for (const std::string& fragment : fragments) {
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos)
          << "'" << fragment << "' missing from: " << e.what();
    }
  }
}

/// `text` with the first `from` replaced by `to`; fails the test when `from` is absent.
inline std::string replace_once(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

/// Sets (or, given nullopt, unsets) an environment variable for one scope, then restores it.
class ScopedEnvironment {
 public:
  ScopedEnvironment(const char* name, const std::optional<std::string>& value) : name_(name) {
    const char* before = std::getenv(name);
    if (before != nullptr) {
      before_ = before;
    }
    set(value);
  }
  ~ScopedEnvironment() { set(before_); }
  ScopedEnvironment(const ScopedEnvironment&) = delete;
  ScopedEnvironment& operator=(const ScopedEnvironment&) = delete;

 private:
  void set(const std::optional<std::string>& value) {
    if (value) {
      setenv(name_, value->c_str(), 1);
    } else {
      unsetenv(name_);
    }
  }

  const char* name_;
  std::optional<std::string> before_;
};

inline std::string config_path(const std::string& file) {
  return std::string(ARI_DIALOGUE_CONFIG_DIR) + "/" + file;
}

}  // namespace ari_social_sim::dialogue::testing
