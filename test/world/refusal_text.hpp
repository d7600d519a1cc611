#pragma once

#include <string>

#include "ari_social_sim/core/error.hpp"

namespace ari_social_sim::world::test {

/// The text of the Error (a refused request, or with core::ConfigError a refused config) that
/// `request` throws, or "" when it is accepted.
template <class Error = core::RequestError, class Request>
std::string refusal_text(Request request) {
  try {
    request();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace ari_social_sim::world::test
