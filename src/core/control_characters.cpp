#include "ari_social_sim/core/control_characters.hpp"

#include <cstdio>
#include <cstring>

#include "ari_social_sim/core/error.hpp"

namespace ari_social_sim::core {

void check_no_control_characters(const std::string& what, const std::string& text,
                                 const char* allowed_whitespace) {
  for (size_t i = 0; i < text.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    const bool allowed = c != '\0' && std::strchr(allowed_whitespace, c) != nullptr;
    if ((c < 0x20 || c == 0x7f) && !allowed) {
      char byte[8];
      std::snprintf(byte, sizeof(byte), "0x%02x", c);
      throw RequestError(what + ": expected no control characters, got byte " + byte +
                         " at offset " + std::to_string(i));
    }
  }
}

}  // namespace ari_social_sim::core
