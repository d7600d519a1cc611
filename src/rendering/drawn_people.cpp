#include "ari_social_sim/rendering/drawn_people.hpp"

#include <algorithm>

#include "ari_social_sim/world/walked_distance.hpp"

namespace ari_social_sim::rendering {

namespace {
// Stamps closer than this are the same instant (sim time from nanosecond stamps).
constexpr double kSameTime_s = 1e-6;
}  // namespace

DrawnPeople::DrawnPeople(uint64_t appearance_seed) : figures_(appearance_seed) {}

void DrawnPeople::add_state(double time_s, std::vector<world::HumanSnapshot> humans) {
  // A state earlier than the last (a reset) starts the history afresh, and the figures' time with
  // it (else their gait would stand still until time caught up).
  if (!states_.empty() && states_.back().first > time_s) {
    states_.clear();
    figures_time_s_ = 0.0;
  }
  states_.emplace_back(time_s, std::move(humans));
  while (states_.size() > kHistory) {
    states_.pop_front();
  }
}

bool DrawnPeople::has_state_for(double time_s) const {
  return !states_.empty() && states_.back().first >= time_s - kSameTime_s;
}

const std::vector<PosedPerson>& DrawnPeople::pose_at(double time_s) {
  size_t next = 0;  // the first state stamped no earlier than the image, else the last
  while (next + 1 < states_.size() && states_[next].first < time_s - kSameTime_s) {
    ++next;
  }
  const auto& [state_s, humans] = states_[next];
  const double received_s = next > 0 ? states_[next - 1].first : state_s - kDefaultWorldStep_s;
  const double ahead_s = std::max(0.0, time_s - received_s);
  std::vector<FigureInput> people;
  people.reserve(humans.size());
  for (const world::HumanSnapshot& human : humans) {
    FigureInput input = figure_input_of(human);
    input.pose.position += ahead_s * human.velocity_mps;
    input.pose.theta += ahead_s * human.angular_velocity_rps;
    input.walked_m = world::walked_on(input.walked_m, human.velocity_mps, input.seated, ahead_s);
    people.push_back(input);
  }
  figures_time_s_ = std::max(figures_time_s_, time_s);
  figures_.update(figures_time_s_, people);
  return figures_.posed();
}

}  // namespace ari_social_sim::rendering
