#include "ari_social_sim/rendering/people_figures.hpp"

#include <algorithm>
#include <cmath>
#include <set>

namespace ari_social_sim::rendering {
namespace {

// Gait: a stride (two steps) is about 0.8 of stature long at a comfortable speed, and the limbs
// swing fully at a brisk 1.2 m/s.
constexpr double kStrideShare = 0.8;
constexpr double kBriskSpeedMps = 1.2;
// Below this speed a person stands: the 2D world's people drift by millimetres when idle.
constexpr double kStandingSpeedMps = 0.05;
// The mouth opens and closes at a syllable rate while the person speaks.
constexpr double kSyllablesPerSecond = 4.0;
// Gestures rise into place and fall back with this time constant when speech starts and ends,
// and beat on every other syllable (beats fall on stressed syllables).
constexpr double kGestureTimeConstantS = 0.35;

// Each person's syllables start at their own offset, so that speakers do not move in step.
double syllable_phase(double time_s, uint32_t id) {
  return 2.0 * M_PI * kSyllablesPerSecond * time_s + 1.7 * id;
}

}  // namespace

FigureInput figure_input_of(const world::HumanSnapshot& human) {
  FigureInput input;
  input.traits = {human.id, human.age_years, human.gender, human.mask, human.emotion};
  input.pose = human.pose;
  input.velocity_mps = human.velocity_mps;
  input.face_yaw_rad = human.gaze.direction_rad;
  input.head_pitch_rad = human.head_pitch_rad;
  input.speaking = human.speech.is_speaking;
  input.seated = human.posture.seated_fraction();
  input.walked_m = human.walked_m;
  return input;
}

FigureInput figure_input_of(const physics::PersonState& person) {
  FigureInput input;
  input.traits = {person.id, person.age_years, person.gender, person.mask, person.emotion};
  input.pose = person.pose;
  input.velocity_mps = person.velocity_mps;
  input.face_yaw_rad = person.face_yaw_rad;
  input.head_pitch_rad = person.head_pitch_rad;
  input.speaking = person.speaking;
  input.seated = person.seated_fraction;
  input.walked_m = person.walked_m;
  return input;
}

PeopleFigures::PeopleFigures(uint64_t appearance_seed) : appearance_seed_(appearance_seed) {}

void PeopleFigures::update(double time_s, const std::vector<FigureInput>& people) {
  std::set<uint32_t> present;
  mesh_.vertices.clear();
  posed_.clear();
  for (const FigureInput& input : people) {
    const uint32_t id = input.traits.id;
    present.insert(id);
    auto found = people_.find(id);
    if (found == people_.end() || found->second.traits != input.traits) {
      // Someone first seen speaking is already gesturing.
      Person person{input.traits, HumanFigure(appearance_of(input.traits, appearance_seed_)),
                    time_s, input.speaking ? 1.0 : 0.0, WeightShifts(appearance_seed_, id)};
      found = people_.insert_or_assign(id, std::move(person)).first;
    }
    Person& person = found->second;
    // Standing up and sitting down move the body, but the feet stay put: no stride.
    const double speed = input.seated > 0.0 ? 0.0 : input.velocity_mps.norm();
    const double dt = std::max(0.0, time_s - person.last_time_s);
    person.last_time_s = time_s;
    person.gesture += ((input.speaking ? 1.0 : 0.0) - person.gesture) *
                      (1.0 - std::exp(-dt / kGestureTimeConstantS));

    PosedPerson posed;
    posed.id = id;
    posed.figure = &person.figure;
    posed.pose.body = input.pose;
    posed.pose.head_yaw_rad = input.face_yaw_rad;
    posed.pose.head_pitch_rad = input.head_pitch_rad;
    const double stride = kStrideShare * person.figure.appearance().height_m;
    posed.pose.gait_phase_rad = 2.0 * M_PI * std::fmod(input.walked_m, stride) / stride;
    posed.pose.seated = input.seated;
    posed.pose.gait_amplitude =
        speed < kStandingSpeedMps ? 0.0 : std::min(1.0, speed / kBriskSpeedMps);
    const double syllable = syllable_phase(time_s, id);
    posed.pose.mouth_open = input.speaking ? 0.5 + 0.5 * std::sin(syllable) : 0.0;
    posed.pose.gesture = person.gesture;
    posed.pose.gesture_beat = std::sin(0.5 * syllable);
    posed.pose.weight_side = person.weight_shifts.load_side(std::max(0.0, time_s));
    const size_t index = posed_.size();
    posed.body_label = static_cast<uint16_t>(2 * index + 1);
    posed.face_label = static_cast<uint16_t>(2 * index + 2);
    posed.vertices.first = mesh_.vertex_count();
    person.figure.append_posed(posed.pose, posed.body_label, posed.face_label, mesh_);
    posed.vertices.count = mesh_.vertex_count() - posed.vertices.first;
    posed_.push_back(posed);
  }
  for (auto it = people_.begin(); it != people_.end();) {
    it = present.count(it->first) > 0 ? std::next(it) : people_.erase(it);
  }
}

std::optional<PeopleFigures::LabelOwner> PeopleFigures::owner_of(uint16_t label) const {
  if (label == 0 || static_cast<size_t>((label - 1) / 2) >= posed_.size()) {
    return std::nullopt;
  }
  return LabelOwner{static_cast<size_t>((label - 1) / 2), label % 2 == 0};
}

}  // namespace ari_social_sim::rendering
