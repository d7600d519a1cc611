#pragma once

#include <Eigen/Core>
#include <string>

namespace ari_social_sim::core {

/// printf-style formatting into a string, for messages, reports and files that want a fixed
/// number of decimals. The compiler checks `pattern` against the arguments.
std::string format_text(const char* pattern, ...) __attribute__((format(printf, 1, 2)));

/// A coordinate (m, s) as messages show it: two decimals while it is of a building's size
/// ("-4.50"), %g beyond ("1e+300", "inf"), so that a rogue value never prints 300 digits.
std::string coordinate_text(double value);
/// A point as "(x, y)" with coordinate_text.
std::string point_text(const Eigen::Vector2d& point);

}  // namespace ari_social_sim::core
