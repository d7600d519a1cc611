#include "ari_social_sim/scenario/script_runner.hpp"

#include <algorithm>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/rng.hpp"
#include "ari_social_sim/core/rng_streams.hpp"
#include "ari_social_sim/dialogue/exemplar_index.hpp"

namespace ari_social_sim::scenario {
namespace {

template <class... Ts>
struct Overloaded : Ts... {
  using Ts::operator()...;
};
template <class... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;

// Position of an agent in the snapshot: ARI's base_footprint or a human's centre.
std::optional<Eigen::Vector2d> position_of(const AgentRef& agent,
                                           const world::WorldSnapshot& world) {
  if (agent.is_ari()) {
    return world.ari ? std::optional<Eigen::Vector2d>(world.ari->pose.position) : std::nullopt;
  }
  for (const world::HumanSnapshot& human : world.humans) {
    if (human.id == agent.human_id) {
      return human.pose.position;
    }
  }
  return std::nullopt;
}

const world::HumanSnapshot* find_human(model::ObjectId id, const world::WorldSnapshot& world) {
  for (const world::HumanSnapshot& human : world.humans) {
    if (human.id == id) {
      return &human;
    }
  }
  return nullptr;
}

// Nobody of the person's group holds the floor; for a person in no group, the person is silent.
bool floor_free(model::ObjectId person, const world::WorldSnapshot& world) {
  const world::HumanSnapshot* human = find_human(person, world);
  if (human == nullptr) {
    return false;
  }
  for (const world::GroupSnapshot& group : world.groups) {
    if (group.id == human->group_id) {
      return group.speaker == model::kNoObject;
    }
  }
  return !human->speech.is_speaking;
}

// A member of a talking group ARI takes part in is speaking to ARI.
bool ari_addressed(const world::WorldSnapshot& world) {
  return world.ari &&
         std::any_of(
             world.groups.begin(), world.groups.end(), [&](const world::GroupSnapshot& group) {
               return group.robot_joining == world.ari->id && group.addressee == world.ari->id &&
                      group.speaker != model::kNoObject && group.speaker != world.ari->id;
             });
}

// A recogniser's empty final (noise it decoded to nothing) is no utterance to answer.
bool has_words(const std::string& transcript) {
  return !dialogue::normalised_words(transcript).empty();
}

}  // namespace

std::string describe(const Action& action) {
  return std::visit(
      Overloaded{
          [](const SayAction& a) { return "say (" + a.speaker.describe() + ", " + a.act + ")"; },
          [](const SetGoalAction& a) { return "set_goal (" + a.who.describe() + ")"; },
          [](const ApproachAction& a) {
            return "approach (human " + std::to_string(a.person) + ")";
          },
          [](const JoinGroupAction& a) {
            return "join_group (of human " + std::to_string(a.person) + ")";
          },
          [](const CancelNavigationAction&) { return std::string("cancel_navigation"); },
          [](const AddHumanAction& a) { return "add_human (" + std::to_string(a.human.id) + ")"; },
          [](const RemoveHumanAction& a) {
            return "remove_human (" + std::to_string(a.human) + ")";
          },
          [](const CreateGroupAction& a) {
            return "create_group (" + std::to_string(a.group.id) + ")";
          },
          [](const CreateWalkingGroupAction& a) {
            return "create_walking_group (" + std::to_string(a.group.id) + ")";
          },
          [](const AddGroupMembersAction& a) {
            return "add_group_members (" + std::to_string(a.group) + ")";
          },
          [](const SetGroupCentreAction& a) {
            return "set_group_centre (" + std::to_string(a.group) + ")";
          },
          [](const LeaveGroupAction& a) { return "leave_group (" + a.who.describe() + ")"; },
          [](const SetGroupArrangementAction& a) {
            return "set_group_arrangement (" + std::to_string(a.group) + ", " +
                   model::to_string(a.arrangement) + ")";
          },
          [](const SetPostureAction& a) {
            return "set_posture (of human " + std::to_string(a.human) + ", " +
                   world::posture_name(a.posture) + ")";
          },
          [](const ConverseAction&) { return std::string("converse"); },
          [](const StopAction& a) {
            return std::string(a.success ? "stop (success)" : "stop (failure)");
          },
      },
      action);
}

ScriptRunner::ScriptRunner(const Scenario& scenario, uint64_t seed,
                           const dialogue::DialogueSetup* dialogue, Hearing hearing)
    : scenario_(scenario), seed_(seed), heard_lines_(scenario.script) {
  if (dialogue != nullptr) {
    conversation_.emplace(
        *dialogue, core::rng_for(seed, core::rng_streams::kConversation).next_u64(), hearing);
  } else if (scenario.script.interfaces().dialogue) {
    throw core::ConfigError(scenario.scene.path +
                            ": script: expected the dialogue settings for `converse` and "
                            "`dialogue_finished`, got none");
  }
}

const std::string& ScriptRunner::state() const {
  static const std::string kNone;
  return visits_.empty() ? kNone : scenario_.script.states[state_].name;
}

void ScriptRunner::update(const Observations& observations, Commands& commands) {
  if (finished()) {
    return;
  }
  if (!started_) {
    begin(observations, commands);
    if (finished()) {
      return;
    }
  }
  now_s_ = observations.world.time_s - start_s_;
  const std::vector<size_t> finished_lines = transcript_.observe(observations.world);
  label_ari_lines();
  for (size_t line : finished_lines) {
    const TranscriptLine& said = transcript_.lines()[line];
    finished_in_state_.push_back({said.speaker, said.act});
  }
  for (const perception::VoiceTranscript& transcript : observations.transcripts) {
    if (const std::optional<std::string> act = heard_lines_.act_of(transcript.text)) {
      heard_in_state_.push_back(*act);
    } else if (has_words(transcript.text)) {
      not_understood_in_state_ = true;
    }
  }
  addressed_in_state_ = addressed_in_state_ || ari_addressed(observations.world);
  if (observations.dialogue_end && !dialogue_end_) {
    dialogue_end_ = observations.dialogue_end;
  }
  if (conversation_ && conversation_->active()) {
    if (const std::optional<SayAction> turn = conversation_->update(observations)) {
      if (!run({*turn}, observations, commands)) {
        return;
      }
    }
  }
  if (now_s_ >= scenario_.script.time_limit_s) {
    end(false, "time limit of " + std::to_string(scenario_.script.time_limit_s) +
                   " s reached in state " + state());
    return;
  }
  const State& state = scenario_.script.states[state_];
  for (const Transition& transition : state.transitions) {
    const bool fires = std::all_of(transition.when.begin(), transition.when.end(),
                                   [&](const Condition& c) { return holds(c, observations); });
    if (!fires) {
      continue;
    }
    if (run(transition.actions, observations, commands)) {
      enter(scenario_.script.state_index(transition.next), observations, commands);
    }
    return;
  }
}

void ScriptRunner::label_ari_lines() {
  const auto& lines = transcript_.lines();
  for (; lines_labelled_ < lines.size(); ++lines_labelled_) {
    if (!lines[lines_labelled_].speaker.is_ari()) {
      continue;
    }
    const auto said = std::find_if(ari_says_.begin(), ari_says_.end(), [&](const SayAction& a) {
      return a.text == lines[lines_labelled_].text;
    });
    if (said != ari_says_.end()) {
      transcript_.relabel(lines_labelled_, said->act);
      ari_says_.erase(ari_says_.begin(), said + 1);
    }
  }
}

void ScriptRunner::begin(const Observations& observations, Commands& commands) {
  started_ = true;
  start_s_ = observations.world.time_s;
  now_s_ = 0.0;
  for (size_t i = 0; i < scenario_.script.random_groups.size(); ++i) {
    core::Rng rng = core::rng_for(seed_, core::rng_streams::kRandomGroups, i);
    const GeneratedGroup generated = generate_group(scenario_.script.random_groups[i], rng);
    std::vector<Action> setup;
    for (const world::HumanSpec& human : generated.humans) {
      setup.emplace_back(AddHumanAction{human});
    }
    setup.emplace_back(CreateGroupAction{generated.group});
    if (!run(setup, observations, commands)) {
      return;
    }
  }
  enter(scenario_.script.state_index(scenario_.script.start), observations, commands);
}

void ScriptRunner::enter(size_t state, const Observations& observations, Commands& commands) {
  if (conversation_) {
    conversation_->stop();  // a conversation lasts as long as the state that started it
  }
  state_ = state;
  state_enter_s_ = now_s_;
  finished_in_state_.clear();
  heard_in_state_.clear();
  not_understood_in_state_ = false;
  addressed_in_state_ = false;
  record_visit(scenario_.script.states[state].name);
  run(scenario_.script.states[state].on_enter, observations, commands);
}

void ScriptRunner::record_visit(const std::string& state) {
  // A re-entry of the last recorded state, unless visits past the record came between.
  if (unrecorded_visits_ == 0 && !visits_.empty() && visits_.back().state == state) {
    ++visits_.back().entries;
  } else if (visits_.size() < kMaxRecordedVisits) {
    visits_.push_back({state, now_s_});
  } else {
    unrecorded_from_s_ = unrecorded_visits_ == 0 ? now_s_ : unrecorded_from_s_;
    ++unrecorded_visits_;
  }
}

bool ScriptRunner::holds(const Condition& condition, const Observations& observations) const {
  const world::WorldSnapshot& world = observations.world;
  return std::visit(
      Overloaded{
          [&](const DistanceCondition& c) {
            const auto from = position_of(c.from, world);
            const auto to = c.to_agent ? position_of(*c.to_agent, world)
                                       : std::optional<Eigen::Vector2d>(c.to_point);
            if (!from || !to) {
              return false;
            }
            const double distance_m = (*from - *to).norm();
            return c.below ? distance_m < c.distance_m : distance_m > c.distance_m;
          },
          [&](const SpeechFinishedCondition& c) {
            return std::any_of(finished_in_state_.begin(), finished_in_state_.end(),
                               [&](const FinishedAct& f) {
                                 return f.speaker == c.speaker && act_matches(c.act, f.act);
                               });
          },
          [&](const GoalReachedCondition& c) {
            if (c.who.is_ari()) {
              return observations.navigation.state == NavigationState::kSucceeded;
            }
            const world::HumanSnapshot* human = find_human(c.who.human_id, world);
            return human != nullptr && human->goal.has_value() &&
                   (human->pose.position - human->goal->position).norm() <= c.tolerance_m;
          },
          [&](const NavigationFailedCondition&) {
            return observations.navigation.state == NavigationState::kFailed;
          },
          [&](const TimeElapsedCondition& c) { return now_s_ - state_enter_s_ >= c.seconds; },
          [&](const DialogueFinishedCondition&) { return dialogue_end_.has_value(); },
          [&](const FloorFreeCondition& c) { return floor_free(c.person, world); },
          [&](const AddressedCondition&) { return addressed_in_state_; },
          [&](const NotUnderstoodCondition&) { return not_understood_in_state_; },
          [&](const HeardCondition& c) {
            return std::any_of(heard_in_state_.begin(), heard_in_state_.end(),
                               [&](const std::string& act) { return act_matches(c.act, act); });
          },
          [&](const PerceivedGroupCondition& c) {
            return std::any_of(
                observations.perceived_groups.begin(), observations.perceived_groups.end(),
                [&](const PerceivedGroup& group) {
                  return std::all_of(c.members.begin(), c.members.end(), [&](const AgentRef& m) {
                    return std::find(group.members.begin(), group.members.end(), m) !=
                           group.members.end();
                  });
                });
          },
      },
      condition);
}

bool ScriptRunner::run(const std::vector<Action>& actions, const Observations& observations,
                       Commands& commands) {
  for (const Action& action : actions) {
    try {
      std::visit(
          Overloaded{
              [&](const SayAction& a) {
                commands.say(a.speaker, a.act, a.text);
                if (a.speaker.is_ari()) {
                  ari_says_.push_back(a);
                }
              },
              [&](const SetGoalAction& a) {
                if (a.who.is_ari()) {
                  commands.navigate(a.goal);
                } else {
                  commands.set_human_goal(a.who.human_id, a.goal);
                }
              },
              [&](const ApproachAction& a) { approach(a.person, false, observations, commands); },
              [&](const JoinGroupAction& a) { approach(a.person, true, observations, commands); },
              [&](const CancelNavigationAction&) { commands.cancel_navigation(); },
              [&](const AddHumanAction& a) { commands.add_human(a.human); },
              [&](const RemoveHumanAction& a) { commands.remove_human(a.human); },
              [&](const CreateGroupAction& a) { commands.create_group(a.group); },
              [&](const CreateWalkingGroupAction& a) { commands.create_walking_group(a.group); },
              [&](const AddGroupMembersAction& a) {
                commands.add_group_members(a.group, a.members);
              },
              [&](const SetGroupCentreAction& a) { commands.set_group_centre(a.group, a.centre); },
              [&](const LeaveGroupAction& a) {
                // ARI by its world id; none (0) is refused by the world as unknown.
                const model::ObjectId ari =
                    observations.world.ari ? observations.world.ari->id : model::kNoObject;
                commands.leave_group(a.who.is_ari() ? ari : a.who.human_id);
              },
              [&](const SetGroupArrangementAction& a) {
                commands.set_group_arrangement(a.group, a.arrangement, a.heading_rad);
              },
              [&](const SetPostureAction& a) { commands.set_posture(a.human, a.posture); },
              [&](const ConverseAction&) { conversation_->start(); },
              [&](const StopAction& a) { end(a.success, a.reason); },
          },
          action);
    } catch (const core::Error& e) {
      const std::string where = visits_.empty() ? "setup" : "state " + state();
      end(false, where + ": " + describe(action) + " refused: " + e.what());
    }
    if (finished()) {
      return false;
    }
  }
  return true;
}

void ScriptRunner::approach(model::ObjectId human, bool join_group,
                            const Observations& observations, Commands& commands) {
  const auto person = observations.person_ids.find(human);
  if (person != observations.person_ids.end()) {
    commands.approach(person->second, join_group);
    return;
  }
  // Navigation has no name for the human yet: the same failure as a goal it rejects, so that
  // the script's navigation_failed transitions apply.
  const world::HumanSnapshot* found = find_human(human, observations.world);
  const std::string name = found != nullptr && !found->name.empty() ? " (" + found->name + ")" : "";
  commands.fail_navigation("human " + std::to_string(human) + name +
                           " is not perceived as any person yet");
}

void ScriptRunner::end(bool success, const std::string& reason) {
  outcome_ = Outcome{success, reason, state(), now_s_};
}

void ScriptRunner::abort(const std::string& reason) {
  if (!finished()) {
    end(false, reason);
  }
}

void ScriptRunner::interrupt(const std::string& cause) {
  if (!finished()) {
    end(false, cause);
    outcome_->interrupted = true;
  }
}

}  // namespace ari_social_sim::scenario
