#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "ari_social_sim/core/error.hpp"

namespace ari_social_sim::world::test {

/// Runs `load` and expects a core::ConfigError whose message names `path` and every fragment.
template <class Load>
void expect_config_error(Load load, const std::string& path,
                         const std::vector<std::string>& fragments) {
  try {
    load();
    FAIL() << "accepted " << path;
  } catch (const core::ConfigError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(path), std::string::npos) << message;
    for (const std::string& fragment : fragments) {
      EXPECT_NE(message.find(fragment), std::string::npos)
          << "'" << fragment << "' not in: " << message;
    }
  }
}

}  // namespace ari_social_sim::world::test
