#pragma once

#include <map>
#include <string>
#include <vector>

#include "ari_social_sim/core/rng.hpp"
#include "ari_social_sim/model/occupancy_grid.hpp"
#include "ari_social_sim/perception/ari_sensors.hpp"
#include "ari_social_sim/perception/asr_errors.hpp"
#include "ari_social_sim/perception/perception_config.hpp"
#include "ari_social_sim/perception/perception_frame.hpp"
#include "ari_social_sim/perception/transient_ids.hpp"
#include "ari_social_sim/world/world_snapshot.hpp"

namespace ari_social_sim::perception {

/// D6.4 §3.5.4 SpeechSensor: voices and speech as ARI's microphone array and ASR report them.
///
/// A human is audible when within the microphone's max_distance and the straight line to them
/// crosses no blocking cell of the sound map (walls: a person in another room is not heard).
/// While an audible human speaks, each new word is passed through AsrErrors and the transcript so
/// far is reported as an `incremental` result; when the act ends (or the speaker stops being
/// audible) the transcript is reported once as `final_text`. Words are heard while they are the
/// current word of the speaker's SpeechGenerator, so frames must come at least at the word rate.
/// An utterance is attributed to the voice of another audible human at misattribution_rate (when
/// there is one). Each human's voice has one id; it is tracked while an utterance attributed to
/// it goes on and for voice_timeout after.
class SpeechListener {
 public:
  SpeechListener(const PerceptionConfig& config, TransientIds& ids, core::Rng rng);

  /// Appends the tracked voices of this frame to `voices`, ordered by human id. `sound_map` is
  /// null when nothing blocks sound.
  void update(const world::WorldSnapshot& snapshot, const AriSensors& sensors,
              const model::OccupancyGrid* sound_map, int occupied_threshold,
              std::vector<PerceivedVoice>& voices);

  /// Forgets every utterance and voice track (ids already handed out stay used).
  void clear();

  /// Voice tracks (one per human in the world who was heard) and utterances going on.
  size_t voice_count() const { return voices_.size(); }
  size_t utterance_count() const { return utterances_.size(); }

 private:
  struct Utterance {
    model::ObjectId voice_owner{model::kNoObject};  ///< Whose voice it is attributed to.
    double start_s{0.0};
    std::vector<std::string> words;  ///< As spoken.
    int last_heard{-1};              ///< Index of the last word passed to the recogniser.
    std::vector<std::string> transcript;
  };
  struct VoiceTrack {
    std::string id;
    double last_active_s{0.0};
    bool active{false};  ///< An utterance attributed to it goes on.
    std::vector<SpeechResult> results;
    std::string transcript;
  };

  /// Who is within hearing this step, and where each human is in the snapshot.
  struct Hearing {
    std::map<model::ObjectId, size_t> index_of;  ///< Index in the snapshot's humans.
    std::vector<bool> audible;                   ///< By index in the snapshot's humans.
  };

  VoiceTrack& voice_of(model::ObjectId human);
  void finish(const Utterance& utterance, double now_s);
  // The stages of update(), in order.
  Hearing hearing(const std::vector<world::HumanSnapshot>& humans, const AriSensors& sensors,
                  const model::OccupancyGrid* sound_map, int occupied_threshold) const;
  void finish_ended_utterances(const std::vector<world::HumanSnapshot>& humans,
                               const Hearing& hearing, double now_s);
  void hear_new_words(const std::vector<world::HumanSnapshot>& humans, const Hearing& hearing,
                      double now_s);
  void begin_utterance(const std::vector<world::HumanSnapshot>& humans, const Hearing& hearing,
                       size_t speaker, Utterance& utterance);
  void report_voices(const std::vector<world::HumanSnapshot>& humans, const Hearing& hearing,
                     double now_s, std::vector<PerceivedVoice>& voices);

  const PerceptionConfig& config_;
  TransientIds& ids_;
  core::Rng rng_;
  AsrErrors asr_;
  std::map<model::ObjectId, Utterance> utterances_;  ///< By speaker.
  std::map<model::ObjectId, VoiceTrack> voices_;     ///< By voice owner.
};

}  // namespace ari_social_sim::perception
