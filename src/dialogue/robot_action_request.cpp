#include "ari_social_sim/dialogue/robot_action_request.hpp"

#include <algorithm>
#include <cstdio>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/dialogue/dialogue_act.hpp"

namespace ari_social_sim::dialogue {
namespace {

// The byte offset of the first byte that breaks UTF-8 (RFC 3629: no overlong forms, no
// surrogates, nothing above U+10FFFF) or is a control character other than tab and newline;
// text.size() when there is none.
size_t first_bad_byte(const std::string& text) {
  size_t i = 0;
  while (i < text.size()) {
    const auto byte = static_cast<unsigned char>(text[i]);
    if (byte < 0x80) {
      if ((byte < 0x20 && byte != '\t' && byte != '\n') || byte == 0x7f) {
        return i;
      }
      ++i;
      continue;
    }
    // Length of the sequence and the allowed range of its second byte.
    size_t length = 0;
    unsigned char low = 0x80, high = 0xbf;
    if (byte >= 0xc2 && byte <= 0xdf) {
      length = 2;
    } else if (byte >= 0xe0 && byte <= 0xef) {
      length = 3;
      low = byte == 0xe0 ? 0xa0 : 0x80;
      high = byte == 0xed ? 0x9f : 0xbf;
    } else if (byte >= 0xf0 && byte <= 0xf4) {
      length = 4;
      low = byte == 0xf0 ? 0x90 : 0x80;
      high = byte == 0xf4 ? 0x8f : 0xbf;
    } else {
      return i;
    }
    if (i + length > text.size()) {
      return i;
    }
    for (size_t k = 1; k < length; ++k) {
      const auto next = static_cast<unsigned char>(text[i + k]);
      if (next < (k == 1 ? low : 0x80) || next > (k == 1 ? high : 0xbf)) {
        return i;
      }
    }
    i += length;
  }
  return text.size();
}

}  // namespace

void check_spoken_text(const std::string& text, const std::string& field) {
  if (text.size() > kMaxSpokenTextBytes) {
    throw core::RequestError(field + ": expected at most " + std::to_string(kMaxSpokenTextBytes) +
                             " bytes, got " + std::to_string(text.size()));
  }
  const size_t bad = first_bad_byte(text);
  if (bad < text.size()) {
    char code[8];
    std::snprintf(code, sizeof(code), "0x%02x", static_cast<unsigned char>(text[bad]));
    throw core::RequestError(field + ": expected UTF-8 text without control characters, got byte " +
                             code + " at " + std::to_string(bad));
  }
}

RobotAction robot_action_from(const std::vector<std::string>& acts,
                              const std::vector<std::string>& addressees, const std::string& text,
                              const std::vector<std::string>& roles) {
  if (acts.size() > kMaxRobotActs) {
    throw core::RequestError("acts: expected at most " + std::to_string(kMaxRobotActs) +
                             " acts, got " + std::to_string(acts.size()));
  }
  RobotAction action;
  for (size_t i = 0; i < acts.size(); ++i) {
    const std::string field = "acts[" + std::to_string(i) + "]";
    check_spoken_text(acts[i], field);
    try {
      action.acts.push_back(parse_act(acts[i], field));
    } catch (const core::ConfigError& e) {
      throw core::RequestError(e.what());
    }
  }
  for (size_t i = 0; i < addressees.size(); ++i) {
    const std::string& addressee = addressees[i];
    const std::string field = "addressees[" + std::to_string(i) + "]";
    if (std::find(roles.begin(), roles.end(), addressee) == roles.end()) {
      check_spoken_text(addressee, field);  // so that the message below prints it safely
      throw core::RequestError(field + ": expected one of the humans' roles, got '" + addressee +
                               "'");
    }
    const auto before = addressees.begin() + static_cast<std::ptrdiff_t>(i);
    if (std::find(addressees.begin(), before, addressee) != before) {
      throw core::RequestError(field + ": expected each role once, got '" + addressee + "' again");
    }
  }
  action.addressees = addressees;
  check_spoken_text(text, "text");
  action.text = text;
  return action;
}

}  // namespace ari_social_sim::dialogue
