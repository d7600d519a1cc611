#pragma once

#include <limits>
#include <string>

namespace ari_social_sim::core {

/// Allowed interval for a number read from a file or held by a config field (config_fields.hpp);
/// part of the error message on violation.
struct Bounds {
  double min{-std::numeric_limits<double>::infinity()};
  double max{std::numeric_limits<double>::infinity()};
  bool min_exclusive{false};

  bool contains(double value) const;
  std::string describe() const;
};

inline Bounds positive() {
  return {0.0, std::numeric_limits<double>::infinity(), true};
}
inline Bounds non_negative() {
  return {0.0, std::numeric_limits<double>::infinity(), false};
}
inline Bounds between(double min, double max) {
  return {min, max, false};
}

}  // namespace ari_social_sim::core
