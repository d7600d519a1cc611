#include "ari_social_sim/audio/voice_tracks.hpp"

#include <cmath>

namespace ari_social_sim::audio {
namespace {

double angle_between(double a_rad, double b_rad) {
  return std::abs(std::remainder(a_rad - b_rad, 2.0 * M_PI));
}

}  // namespace

const std::string& VoiceTracks::voice_from(double azimuth_rad) {
  Track* nearest = nullptr;
  for (Track& track : tracks_) {
    const double apart = angle_between(track.azimuth_rad, azimuth_rad);
    if (apart <= separation_rad_ &&
        (nearest == nullptr || apart < angle_between(nearest->azimuth_rad, azimuth_rad))) {
      nearest = &track;
    }
  }
  if (nearest == nullptr) {
    tracks_.push_back({"voice" + std::to_string(tracks_.size() + 1), azimuth_rad});
    return tracks_.back().id;
  }
  nearest->azimuth_rad = azimuth_rad;
  return nearest->id;
}

std::vector<std::string> VoiceTracks::ids() const {
  std::vector<std::string> ids;
  for (const Track& track : tracks_) {
    ids.push_back(track.id);
  }
  return ids;
}

}  // namespace ari_social_sim::audio
