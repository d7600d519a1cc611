#pragma once

// Tests that read a public data set (docs/data.md) run when it is present and are reported as
// skipped, with the reason and the command that fetches it, when it is not. The skip message
// starts with kDataSetSkipPrefix so that the test summary can name such skips, and CI, which
// has every set, can refuse them.

#include <gtest/gtest.h>

#include "ari_social_sim/core/data_sets.hpp"

namespace ari_social_sim::test {

inline constexpr const char* kDataSetSkipPrefix = "data set missing: ";

}  // namespace ari_social_sim::test

/// Skips the current test unless data set `name` is present; use at the top of a test body.
#define ARI_SKIP_WITHOUT_DATA_SET(name)                                     \
  do {                                                                      \
    if (!ari_social_sim::core::data_set_present(name)) {                    \
      GTEST_SKIP() << ari_social_sim::test::kDataSetSkipPrefix              \
                   << ari_social_sim::core::missing_data_set_message(name); \
    }                                                                       \
  } while (false)
