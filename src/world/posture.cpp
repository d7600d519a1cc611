#include "ari_social_sim/world/posture.hpp"

#include <algorithm>

namespace ari_social_sim::world {

const char* posture_name(Posture posture) {
  return core::choice_name(posture, kPostures);
}

double PostureState::seated_fraction() const {
  return posture == Posture::kSitting ? progress : 1.0 - progress;
}

void PostureState::change_to(Posture target) {
  if (target == posture) {
    return;
  }
  // The body is where the old change had got to: the new one starts there, so it takes only
  // the share of kPostureChangeS that is left.
  posture = target;
  progress = 1.0 - progress;
}

double PostureState::advance(double dt_s) {
  if (!is_changing()) {
    return 0.0;
  }
  // The last step may be shorter than dt_s: the speed is what moves the body by the rest exactly.
  const double step = std::min(dt_s / kPostureChangeS, 1.0 - progress);
  progress = std::min(1.0, progress + dt_s / kPostureChangeS);
  const double speed_mps = kSeatToFeetM * step / dt_s;
  return posture == Posture::kStanding ? speed_mps : -speed_mps;
}

}  // namespace ari_social_sim::world
