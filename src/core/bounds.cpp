#include "ari_social_sim/core/bounds.hpp"

#include <cmath>

#include "ari_social_sim/core/number_text.hpp"

namespace ari_social_sim::core {

bool Bounds::contains(double value) const {
  if (std::isnan(value)) {
    return false;
  }
  const bool above_min = min_exclusive ? value > min : value >= min;
  return above_min && value <= max;
}

std::string Bounds::describe() const {
  const bool has_min = std::isfinite(min);
  const bool has_max = std::isfinite(max);
  if (has_min && has_max) {
    return std::string(min_exclusive ? "(" : "[") + number_text(min) + ", " + number_text(max) +
           "]";
  }
  if (has_min) {
    return std::string(min_exclusive ? "> " : ">= ") + number_text(min);
  }
  if (has_max) {
    return "<= " + number_text(max);
  }
  return "";
}

}  // namespace ari_social_sim::core
