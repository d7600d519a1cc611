#pragma once

#include <sstream>
#include <string>

namespace ari_social_sim::core {

/// A number as error messages show it: six significant digits, "nan", "inf", "1e+300".
inline std::string number_text(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

}  // namespace ari_social_sim::core
