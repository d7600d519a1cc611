#include "ari_social_sim/batch/progress_bar.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ari_social_sim::batch {

std::string format_duration(double seconds) {
  const long total = std::lround(std::max(seconds, 0.0));
  char text[32];
  if (total >= 3600) {
    std::snprintf(text, sizeof(text), "%ld:%02ld:%02ld", total / 3600, total / 60 % 60, total % 60);
  } else {
    std::snprintf(text, sizeof(text), "%ld:%02ld", total / 60, total % 60);
  }
  return text;
}

std::string progress_line(uint64_t done, uint64_t total, double elapsed_s, int bar_width) {
  const double fraction = total == 0 ? 1.0 : std::min(1.0, static_cast<double>(done) / total);
  const int filled = static_cast<int>(std::floor(fraction * bar_width));
  std::string line = "[" + std::string(filled, '#') + std::string(bar_width - filled, '-') + "]";
  const int digits = static_cast<int>(std::to_string(total).size());
  char text[96];
  std::snprintf(text, sizeof(text), " %*lu/%lu episodes", digits, static_cast<unsigned long>(done),
                static_cast<unsigned long>(total));
  line += text;
  if (done > 0 && elapsed_s > 0.0) {
    const double per_minute = 60.0 * static_cast<double>(done) / elapsed_s;
    const double left_s = static_cast<double>(total - std::min(done, total)) * elapsed_s / done;
    std::snprintf(text, sizeof(text), "  %.1f ep/min  ETA %s", per_minute,
                  format_duration(left_s).c_str());
    line += text;
  }
  return line;
}

}  // namespace ari_social_sim::batch
