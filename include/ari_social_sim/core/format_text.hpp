#pragma once

#include <string>

namespace ari_social_sim::core {

/// printf-style formatting into a string, for messages, reports and files that want a fixed
/// number of decimals. The compiler checks `pattern` against the arguments.
std::string format_text(const char* pattern, ...) __attribute__((format(printf, 1, 2)));

}  // namespace ari_social_sim::core
