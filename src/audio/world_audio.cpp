#include "ari_social_sim/audio/world_audio.hpp"

#include <algorithm>
#include <cmath>

#include "ari_social_sim/audio/timed_speech.hpp"
#include "ari_social_sim/model/ari_sensor_geometry.hpp"

namespace ari_social_sim::audio {
namespace {

// Where voices come from: an adult's mouth, a child's (under 14), and ARI's loudspeaker, which
// PAL does not place publicly: taken in the torso below the head, in base_footprint.
constexpr double kAdultMouthHeightM = 1.55;
constexpr double kChildMouthHeightM = 1.15;
constexpr double kAriLoudspeakerX = -0.15;
constexpr double kAriLoudspeakerZ = 1.2;

Eigen::Isometry3d planar_pose(const core::Pose2& pose) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.translation() = Eigen::Vector3d(pose.position.x(), pose.position.y(), 0.0);
  X.linear() = Eigen::AngleAxisd(pose.theta, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return X;
}

int64_t sample_of(double time_s) {
  return static_cast<int64_t>(std::llround(time_s * kSampleRateHz));
}

int rate_of(const world::SpeechSnapshot& speech) {
  return std::clamp(static_cast<int>(std::lround(speech.words_per_minute)), 80, 450);
}

Eigen::Vector3d mouth_of(const world::HumanSnapshot& human) {
  const double mouth = human.age_years < 14.0 ? kChildMouthHeightM : kAdultMouthHeightM;
  return {human.pose.position.x(), human.pose.position.y(), mouth};
}

Eigen::Isometry3d array_pose_of(const world::AriSnapshot& ari) {
  Eigen::Isometry3d X_footprint_array = Eigen::Isometry3d::Identity();
  X_footprint_array.translation() =
      Eigen::Vector3d(model::kMicrophoneInFootprint.x_m, model::kMicrophoneInFootprint.y_m,
                      model::kMicrophoneInFootprint.z_m);
  return planar_pose(ari.pose) * X_footprint_array;
}

}  // namespace

std::vector<Wall> walls_of(const model::WorldDescription& world) {
  std::vector<Wall> walls;
  for (const model::StaticObject& object : world.objects) {
    if (object.type != model::ShapeType::kWall) {
      continue;
    }
    const Eigen::Vector2d along(std::cos(object.pose.theta), std::sin(object.pose.theta));
    const Eigen::Vector2d centre = object.pose.position;
    walls.push_back(
        {centre - 0.5 * object.size.x() * along, centre + 0.5 * object.size.x() * along});
  }
  return walls;
}

WorldAudio::WorldAudio(const RoomSettings& room, std::vector<Wall> walls, uint64_t seed,
                       std::shared_ptr<SpeechSynthesizer> synthesizer)
    : mixer_(room, std::move(walls), seed), seed_(seed), synthesizer_(std::move(synthesizer)) {}

bool WorldAudio::starts_utterance(uint64_t id, const world::SpeechSnapshot& speech) {
  Utterance& placed = placed_[id];
  const bool same = placed.start_s == speech.start_s && placed.content == speech.content;
  if (!speech.is_speaking || !same) {
    // Silent now, or saying something else: what was left of the last utterance is not said.
    mixer_.stop_source(id, std::max(mixer_.next_sample(), sample_of(speech.start_s)));
  }
  if (!speech.is_speaking || same || speech.words_per_minute <= 0.0) {
    return false;
  }
  placed = {speech.start_s, speech.content};
  return true;
}

void WorldAudio::place(uint64_t id, const world::SpeechSnapshot& speech, const Voice& voice,
                       bool from_ari) {
  Voice spoken = voice;
  spoken.rate_wpm = rate_of(speech);
  const std::shared_ptr<const Synthesis> synthesis =
      synthesizer_->synthesize(speech.content, spoken);
  truncated_ += synthesis->truncated ? 1 : 0;
  const std::vector<double> onsets =
      word_onsets_s(world::spoken_words(speech.content).size(), speech.words_per_minute);
  auto fitted = std::make_shared<const std::vector<float>>(fit_to_onsets(*synthesis, onsets));
  mixer_.add({id, fitted, sample_of(speech.start_s), from_ari});
}

std::vector<SpeakerDirection> speaker_directions(const world::WorldSnapshot& snapshot) {
  std::vector<SpeakerDirection> directions;
  if (!snapshot.ari) {
    return directions;
  }
  const Eigen::Isometry3d X_array_world = array_pose_of(*snapshot.ari).inverse();
  for (const world::HumanSnapshot& human : snapshot.humans) {
    if (human.speech.is_speaking) {
      const Eigen::Vector3d mouth = X_array_world * mouth_of(human);
      directions.push_back({human.id, std::atan2(mouth.y(), mouth.x()), mouth.norm()});
    }
  }
  return directions;
}

void WorldAudio::observe(const world::WorldSnapshot& snapshot) {
  for (const world::HumanSnapshot& human : snapshot.humans) {
    mixer_.set_source_position(human.id, mouth_of(human));
    if (starts_utterance(human.id, human.speech)) {
      place(human.id, human.speech, voice_for(seed_, human.id, human.gender, human.age_years),
            false);
    }
  }
  if (snapshot.ari) {
    mixer_.set_source_position(
        snapshot.ari->id,
        planar_pose(snapshot.ari->pose) * Eigen::Vector3d(kAriLoudspeakerX, 0.0, kAriLoudspeakerZ));
    mixer_.set_array_pose(array_pose_of(*snapshot.ari));
    if (starts_utterance(snapshot.ari->id, snapshot.ari->speech)) {
      place(snapshot.ari->id, snapshot.ari->speech, ari_voice(), true);
    }
  }
}

std::vector<ArrayChunk> WorldAudio::chunks_until(double time_s) {
  std::vector<ArrayChunk> chunks;
  while (mixer_.next_sample() + static_cast<int64_t>(kChunkSamples) <= sample_of(time_s)) {
    chunks.push_back(mixer_.render(kChunkSamples));
  }
  return chunks;
}

}  // namespace ari_social_sim::audio
