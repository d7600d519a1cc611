#include "ari_social_sim/core/format_text.hpp"

#include <cmath>
#include <cstdarg>
#include <cstdio>

namespace ari_social_sim::core {

std::string format_text(const char* pattern, ...) {
  va_list args;
  va_start(args, pattern);
  va_list measuring;
  va_copy(measuring, args);
  const int length = std::vsnprintf(nullptr, 0, pattern, measuring);
  va_end(measuring);
  std::string text(length > 0 ? static_cast<size_t>(length) : 0, '\0');
  if (length > 0) {
    // C++17 strings own length + 1 bytes, so the terminating NUL has room.
    std::vsnprintf(text.data(), text.size() + 1, pattern, args);
  }
  va_end(args);
  return text;
}

std::string coordinate_text(double value) {
  // Fixed decimals up to a million: beyond, %f writes every digit of the integer part.
  constexpr double kLargestFixed = 1e6;
  return std::abs(value) < kLargestFixed ? format_text("%.2f", value) : format_text("%g", value);
}

std::string point_text(const Eigen::Vector2d& point) {
  return "(" + coordinate_text(point.x()) + ", " + coordinate_text(point.y()) + ")";
}

}  // namespace ari_social_sim::core
