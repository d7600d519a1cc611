#pragma once

#include <cstdint>

namespace ari_social_sim::model {

/// User-facing identifier of any object in the world (wall, furniture, human, ARI), unique and
/// positive. 0 means "none".
using ObjectId = uint32_t;
constexpr ObjectId kNoObject = 0;

}  // namespace ari_social_sim::model
