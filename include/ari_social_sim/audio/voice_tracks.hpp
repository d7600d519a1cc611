#pragma once

#include <string>
#include <vector>

namespace ari_social_sim::audio {

/// Voices told apart by where they come from, as a speech node on a microphone array does: an
/// utterance heard from within `separation_rad` of a known voice's last direction is that voice's
/// (the nearest), otherwise a new voice. Ids are `voice1`, `voice2`, ... in order of first
/// hearing.
class VoiceTracks {
 public:
  explicit VoiceTracks(double separation_rad) : separation_rad_(separation_rad) {}

  /// The id of the voice heard from `azimuth_rad` (any angle), whose direction becomes it.
  const std::string& voice_from(double azimuth_rad);

  /// Every voice heard so far.
  std::vector<std::string> ids() const;

 private:
  struct Track {
    std::string id;
    double azimuth_rad{0.0};
  };
  double separation_rad_;
  std::vector<Track> tracks_;
};

}  // namespace ari_social_sim::audio
