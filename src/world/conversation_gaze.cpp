#include "ari_social_sim/world/conversation_gaze.hpp"

#include <algorithm>
#include <cmath>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/world/simulation.hpp"

namespace ari_social_sim::world {
namespace {

// Standard deviation (rad) of a look away from the body's heading: down or aside, not behind.
constexpr double kLookAwaySpreadRad = 0.6;

}  // namespace

void ConversationGaze::anticipate(model::ObjectId member, model::ObjectId target, double at_s) {
  State& state = states_[member];
  state.anticipated = target;
  state.anticipate_at_s = at_s;
}

void ConversationGaze::step(Simulation& simulation,
                            const std::vector<model::ObjectId>& participants,
                            const GazeRoles& roles, double now_s) {
  for (model::ObjectId member : participants) {
    Human* human = simulation.mutable_human(member);
    if (human == nullptr) {
      continue;  // ARI: its gaze is its head's
    }
    others_.clear();
    std::copy_if(participants.begin(), participants.end(), std::back_inserter(others_),
                 [member](model::ObjectId id) { return id != member; });
    State& state = states_[member];
    update(state, member, others_, roles, now_s);
    const Object* target = simulation.find_object(state.target);
    const Eigen::Vector2d to_target = target != nullptr
                                          ? Eigen::Vector2d(target->centre() - human->centre())
                                          : Eigen::Vector2d::Zero();
    const double direction = target != nullptr
                                 ? std::atan2(to_target.y(), to_target.x())
                                 : core::wrap_angle(human->pose().theta + state.away_rad);
    human->set_conversation_gaze(
        GazeEvent{target != nullptr ? state.target : model::kNoObject, direction, state.since_s});
  }
  // Members who left the group look where they please again.
  for (auto it = states_.begin(); it != states_.end();) {
    if (std::find(participants.begin(), participants.end(), it->first) == participants.end()) {
      if (Human* human = simulation.mutable_human(it->first)) {
        human->set_conversation_gaze(std::nullopt);
      }
      it = states_.erase(it);
    } else {
      ++it;
    }
  }
}

void ConversationGaze::release(Simulation& simulation) {
  for (const auto& [member, state] : states_) {
    if (Human* human = simulation.mutable_human(member)) {
      human->set_conversation_gaze(std::nullopt);
    }
  }
  states_.clear();
}

void ConversationGaze::update(State& state, model::ObjectId member,
                              const std::vector<model::ObjectId>& others, const GazeRoles& roles,
                              double now_s) {
  const bool speaking = roles.speaker == member;
  if (state.speaker_seen != roles.speaker) {
    state.speaker_seen = roles.speaker;
    state.end_look_done = false;
    state.next_change_s = now_s;
    if (speaking && rng_.bernoulli(shares_.speaker_look_away_at_start)) {
      look(state, model::kNoObject, now_s);
      state.away_rad = rng_.normal(0.0, kLookAwaySpreadRad);
      state.next_change_s = now_s + rng_.exponential(shares_.look_away_mean_s);
      return;
    }
  }
  if (state.anticipated != model::kNoObject && now_s + 1e-9 >= state.anticipate_at_s) {
    if (!speaking) {
      look(state, state.anticipated, state.anticipate_at_s);
      state.next_change_s = now_s + rng_.exponential(shares_.mean_dwell_s);
    }
    state.anticipated = model::kNoObject;
  }
  if (speaking && !state.end_look_done &&
      now_s + shares_.end_of_turn_look_s >= roles.utterance_end_s) {
    state.end_look_done = true;
    const model::ObjectId addressee = roles.addressee != model::kNoObject
                                          ? roles.addressee
                                          : others[rng_.uniform_index(others.size())];
    look(state, addressee, now_s);
    state.next_change_s = roles.utterance_end_s + rng_.exponential(shares_.mean_dwell_s);
    return;
  }
  if (now_s + 1e-9 < state.next_change_s) {
    return;
  }
  if (speaking) {
    draw(state, others, roles.addressee, shares_.speaker_at_addressee, shares_.speaker_at_other);
  } else {
    draw(state, others, roles.speaker, shares_.listener_at_speaker, shares_.listener_at_other);
  }
  state.since_s = now_s;
  state.next_change_s = now_s + rng_.exponential(shares_.mean_dwell_s);
}

void ConversationGaze::draw(State& state, const std::vector<model::ObjectId>& others,
                            model::ObjectId focus, double at_focus, double at_other) {
  const double draw = rng_.uniform();
  if (focus != model::kNoObject && draw < at_focus) {
    state.target = focus;
    return;
  }
  // Without a focus (a speaker addressing the whole group) its share goes round the others too.
  bystanders_.clear();
  std::copy_if(others.begin(), others.end(), std::back_inserter(bystanders_),
               [focus](model::ObjectId id) { return id != focus; });
  if (!bystanders_.empty() && draw < at_focus + at_other) {
    state.target = bystanders_[rng_.uniform_index(bystanders_.size())];
    return;
  }
  state.target = model::kNoObject;
  state.away_rad = rng_.normal(0.0, kLookAwaySpreadRad);
}

void ConversationGaze::look(State& state, model::ObjectId target, double now_s) {
  state.target = target;
  state.since_s = now_s;
}

}  // namespace ari_social_sim::world
