#pragma once

#include <string>

namespace ari_social_sim::core {

/// `text` as a JSON string literal, quotes included (", \, control characters escaped), for the
/// JSON files the tools write by hand: the same text always gives the same bytes.
std::string json_string(const std::string& text);

}  // namespace ari_social_sim::core
