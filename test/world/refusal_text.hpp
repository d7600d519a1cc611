#pragma once

#include <string>

#include "ari_social_sim/core/error.hpp"

namespace ari_social_sim::world::test {

/// The text of the core::RequestError `request` throws, or "" when it is accepted.
template <class Request>
std::string refusal_text(Request request) {
  try {
    request();
  } catch (const core::RequestError& e) {
    return e.what();
  }
  return "";
}

}  // namespace ari_social_sim::world::test
