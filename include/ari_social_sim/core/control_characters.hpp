#pragma once

#include <string>

namespace ari_social_sim::core {

/// Throws core::RequestError "<what>: expected no control characters, got byte 0x.. at offset N"
/// for a control character in `text` (NUL included: a string that C code, a log or a bag reader
/// would cut or show garbled), the whitespace of `allowed_whitespace` excepted.
void check_no_control_characters(const std::string& what, const std::string& text,
                                 const char* allowed_whitespace);

}  // namespace ari_social_sim::core
