#include "ari_social_sim/dialogue/user_simulation.hpp"

#include <algorithm>
#include <set>

#include "ari_social_sim/core/config_check.hpp"

namespace ari_social_sim::dialogue {
namespace {

DialogueAct bare(const std::string& intent) {
  return DialogueAct{intent, {}, ""};
}

bool addressed_to_robot(const Utterance& u) {
  return std::find(u.addressees.begin(), u.addressees.end(), kRobot) != u.addressees.end();
}

// Path of ARI's last informative act (what r-confirm and r-repet refer to); empty if none.
std::vector<std::string> last_robot_path(const std::vector<DialogueAct>& acts) {
  for (auto act = acts.rbegin(); act != acts.rend(); ++act) {
    if (!act->path().empty()) {
      return act->path();
    }
  }
  return {};
}

}  // namespace

std::string UserSimulationConfig::bad_role() const {
  if (roles.empty()) {
    return "[]";
  }
  std::set<std::string> seen;
  for (const std::string& role : roles) {
    if (role.empty() || role == kRobot || !seen.insert(role).second) {
      return "'" + role + "'";
    }
  }
  return "";
}

void UserSimulationConfig::validate() const {
  core::check_fields(*this, "UserSimulationConfig");
}

UserSimulation::UserSimulation(UserSimulationConfig config, const Domain& domain,
                               const UserModel& model, const std::string& model_source,
                               const Nlg& nlg, const ErrorModel& errors, const TurnTiming& timing)
    : config_(std::move(config)),
      domain_(domain),
      model_(model),
      nlg_(nlg),
      errors_(errors),
      timing_(timing) {
  config_.validate();
  for (const std::string& role : config_.roles) {
    role_models_.push_back(&model_.role(role, model_source));
  }
}

void UserSimulation::reset(core::Rng& rng) {
  agenda_ = Agenda::sample(domain_, model_.goals, config_.roles, rng);
  humans_.clear();
  for (const std::string& role : config_.roles) {
    const unsigned span = config_.max_patience - config_.min_patience + 1;
    humans_.push_back(
        HumanAgent{role, static_cast<int>(config_.min_patience + rng.uniform_index(span)), false});
  }
  last_addresser_ = -1;
  relay_goal_ = -1;
  last_robot_acts_.clear();
}

bool UserSimulation::finished() const {
  const bool all_left =
      std::all_of(humans_.begin(), humans_.end(), [](const HumanAgent& h) { return h.left; });
  return all_left || agenda_.all_done();
}

int UserSimulation::other_human(size_t speaker) const {
  std::vector<int> others;
  for (size_t i = 0; i < humans_.size(); ++i) {
    if (i != speaker && !humans_[i].left) {
      others.push_back(static_cast<int>(i));
    }
  }
  return others.empty() ? -1 : others.front();
}

void UserSimulation::penalise(int goal_index) {
  TrackedGoal& goal = agenda_.goals()[goal_index];
  for (HumanAgent& human : humans_) {
    if (Agenda::owns(goal, human.role)) {
      human.patience -= 1;
    }
  }
  if (goal.status == GoalStatus::kStated && goal.asks >= static_cast<int>(config_.max_asks)) {
    goal.status = GoalStatus::kFailed;
  }
  // Out of patience: the human gives up every goal it still has (PyDial: agenda -> bye).
  for (const HumanAgent& human : humans_) {
    if (human.patience > 0) {
      continue;
    }
    for (TrackedGoal& g : agenda_.goals()) {
      if ((g.status == GoalStatus::kWaiting || g.status == GoalStatus::kStated) &&
          Agenda::owns(g, human.role)) {
        g.status = GoalStatus::kFailed;
      }
    }
  }
}

void UserSimulation::hear_robot(Utterance& robot) {
  last_robot_acts_ = robot.acts;
  const int focus = agenda_.focus();
  bool wrong_answer = false;
  bool focus_handled = false;
  for (const DialogueAct& act : robot.acts) {
    if (const auto target = domain_.goal_of_answer(act)) {
      for (size_t i = 0; i < agenda_.goals().size(); ++i) {
        TrackedGoal& g = agenda_.goals()[i];
        if (g.goal.same_target(*target) &&
            (g.status == GoalStatus::kStated || g.status == GoalStatus::kWaiting)) {
          g.status = GoalStatus::kResolved;
          g.satisfied = true;
          robot.goals.push_back(GoalLabel{GoalLabelKind::kAnswered, g.goal});
          focus_handled = focus_handled || static_cast<int>(i) == focus;
        }
      }
      // Informing about anything but the question just asked is a wrong answer to the asker.
      wrong_answer = true;
    } else if (act.intent == "cant-help" && focus >= 0 && !focus_handled) {
      // The user takes a cant-help as the answer; it is the right one only when ARI cannot know.
      TrackedGoal& g = agenda_.goals()[focus];
      const DomainObject* object = domain_.find_object(g.goal);
      focus_handled = true;
      g.status = GoalStatus::kResolved;
      g.satisfied = object != nullptr && !object->ari_knows;
      if (!g.satisfied) {
        penalise(focus);
      }
    }
  }
  if (wrong_answer && focus >= 0 && !focus_handled) {
    penalise(focus);
  }
}

size_t UserSimulation::pick_responder(const std::vector<Utterance>& transcript,
                                      core::Rng& rng) const {
  std::vector<size_t> active;
  for (size_t i = 0; i < humans_.size(); ++i) {
    if (!humans_[i].left) {
      active.push_back(i);
    }
  }
  if (active.size() == 1) {
    return active.front();
  }
  int preferred = last_addresser_;
  if (!transcript.empty() && !transcript.back().is_robot()) {
    // ARI stayed silent: the last human speaker is the one who may go on.
    const std::string& role = transcript.back().speaker;
    for (size_t i = 0; i < humans_.size(); ++i) {
      preferred = humans_[i].role == role ? static_cast<int>(i) : preferred;
    }
  }
  if (preferred >= 0 && !humans_[preferred].left && rng.bernoulli(model_.same_responder)) {
    return static_cast<size_t>(preferred);
  }
  std::vector<size_t> others;
  for (size_t i : active) {
    if (static_cast<int>(i) != preferred) {
      others.push_back(i);
    }
  }
  return others[rng.uniform_index(others.size())];
}

const IntentDistribution& UserSimulation::context_row(size_t speaker,
                                                      const Utterance* previous) const {
  const RoleModel& role = *role_models_[speaker];
  if (previous == nullptr) {
    return role.opening;
  }
  if (previous->is_robot()) {
    return role.after_robot.row(previous->first_intent());
  }
  if (previous->speaker == humans_[speaker].role) {
    return role.after_self.row(previous->first_intent());
  }
  return role.after_other.row(previous->first_intent());
}

UserSimulation::Draft UserSimulation::close_or_leave(size_t speaker) {
  Draft draft;
  HumanAgent& human = humans_[speaker];
  const std::vector<int> closable = agenda_.closable(human.role);
  if (!closable.empty()) {
    draft.acts.push_back(bare("thank"));
    for (int i : closable) {
      agenda_.goals()[i].status = GoalStatus::kClosed;
      draft.goals.push_back(GoalLabel{GoalLabelKind::kClosed, agenda_.goals()[i].goal});
    }
  } else if (agenda_.done(human.role)) {
    draft.acts.push_back(bare("bye"));
    human.left = true;
  } else {
    draft.acts.push_back(bare("acknowledge"));
  }
  draft.to_other = 0;
  return draft;
}

UserSimulation::Draft UserSimulation::state_goal(size_t speaker, const Utterance* previous,
                                                 core::Rng& rng) {
  const HumanAgent& human = humans_[speaker];
  const int other = other_human(speaker);
  int index = -1;
  bool relayed = false;
  // Relay: the other human just told us a goal; we put it to ARI.
  if (previous != nullptr && !previous->is_robot() && previous->speaker != human.role &&
      relay_goal_ >= 0 && agenda_.goals()[relay_goal_].status == GoalStatus::kWaiting) {
    index = relay_goal_;
    relayed = true;
  }
  if (index < 0) {
    const int open = agenda_.open_goal(human.role);
    if (open >= 0 && agenda_.goals()[open].asks < static_cast<int>(config_.max_asks) &&
        rng.bernoulli(config_.reask_probability)) {
      index = open;
    } else {
      index = agenda_.next_waiting(human.role, rng);
    }
  }
  if (index < 0) {
    return close_or_leave(speaker);
  }
  Draft draft;
  const TrackedGoal& goal = agenda_.goals()[index];
  const std::vector<DialogueAct> asks = domain_.ask_acts(goal.goal);
  draft.acts.push_back(asks[rng.uniform_index(asks.size())]);
  draft.goals.push_back(GoalLabel{GoalLabelKind::kStated, goal.goal});
  const bool to_other = !relayed && other >= 0 &&
                        rng.bernoulli(role_models_[speaker]->to_other_probability("request"));
  if (to_other) {
    relay_goal_ = index;
    draft.to_other = 1;
  } else {
    agenda_.mark_stated(index);
    relay_goal_ = relayed ? -1 : relay_goal_;
    draft.to_other = 0;
  }
  return draft;
}

bool UserSimulation::said_by_other_human(size_t speaker, const Utterance* previous) const {
  return previous != nullptr && !previous->is_robot() && previous->speaker != humans_[speaker].role;
}

UserSimulation::Draft UserSimulation::thank_and_close(size_t speaker, const std::string& intent) {
  Draft draft;
  draft.acts.push_back(bare(intent));
  for (int i : agenda_.closable(humans_[speaker].role)) {
    agenda_.goals()[i].status = GoalStatus::kClosed;
    draft.goals.push_back(GoalLabel{GoalLabelKind::kClosed, agenda_.goals()[i].goal});
  }
  return draft;
}

UserSimulation::Draft UserSimulation::say_bye(size_t speaker, const Utterance* previous,
                                              core::Rng& rng) {
  HumanAgent& human = humans_[speaker];
  if (agenda_.done(human.role) || human.patience <= 0) {
    human.left = true;
    Draft draft;
    draft.acts.push_back(bare("bye"));
    return draft;
  }
  return realise(speaker, "thank", previous, rng);
}

UserSimulation::Draft UserSimulation::suggest_goal(size_t speaker, core::Rng& rng) {
  Draft draft;
  const int index = agenda_.next_waiting(humans_[speaker].role, rng);
  if (index < 0 || other_human(speaker) < 0) {
    return draft;  // nothing to suggest: an unannotated remark
  }
  const TrackedGoal& goal = agenda_.goals()[index];
  std::vector<std::string> path = domain_.ask_acts(goal.goal).front().path();
  path.insert(path.begin(), "requesting");
  draft.acts.push_back(DialogueAct::from_path("suggest", std::move(path)));
  draft.goals.push_back(GoalLabel{GoalLabelKind::kStated, goal.goal});
  relay_goal_ = index;
  draft.to_other = 1;
  return draft;
}

UserSimulation::Draft UserSimulation::accept_suggestion(size_t speaker, const Utterance* previous,
                                                        core::Rng& rng) {
  if (said_by_other_human(speaker, previous) && previous->first_intent() == "suggest") {
    Draft draft;
    draft.acts.push_back(DialogueAct::from_path("accept-sugg", previous->acts.front().path()));
    draft.to_other = 1;
    return draft;
  }
  return realise(speaker, "affirm", previous, rng);
}

UserSimulation::Draft UserSimulation::inform_relayed_goal(size_t speaker, const Utterance* previous,
                                                          core::Rng& rng) {
  // The other human answers a goal told to them, when humans may know it (appointment time).
  if (said_by_other_human(speaker, previous) && relay_goal_ >= 0) {
    TrackedGoal& goal = agenda_.goals()[relay_goal_];
    const DomainObject* object = domain_.find_object(goal.goal);
    if (object != nullptr && object->humans_know && goal.status == GoalStatus::kWaiting) {
      Draft draft;
      draft.acts.push_back(DialogueAct::from_path("inform", goal.goal.object));
      draft.goals.push_back(GoalLabel{GoalLabelKind::kAnswered, goal.goal});
      goal.status = GoalStatus::kResolved;
      goal.satisfied = true;
      relay_goal_ = -1;
      draft.to_other = 1;
      return draft;
    }
  }
  return realise(speaker, "acknowledge", previous, rng);
}

UserSimulation::Draft UserSimulation::query_robot(size_t speaker, const std::string& intent,
                                                  const Utterance* previous, core::Rng& rng) {
  const std::vector<std::string> path = last_robot_path(last_robot_acts_);
  if (path.empty()) {
    return realise(speaker, intent == "r-confirm" ? "acknowledge" : "cant-hear", previous, rng);
  }
  Draft draft;
  draft.acts.push_back(DialogueAct::from_path(intent, path));
  draft.to_other = 0;
  return draft;
}

UserSimulation::Draft UserSimulation::realise(size_t speaker, const std::string& intent,
                                              const Utterance* previous, core::Rng& rng) {
  if (intent == "request") {
    return state_goal(speaker, previous, rng);
  }
  if (intent == "thank" || intent == "acknowledge") {
    return thank_and_close(speaker, intent);
  }
  if (intent == "bye") {
    return say_bye(speaker, previous, rng);
  }
  if (intent == "suggest") {
    return suggest_goal(speaker, rng);
  }
  if (intent == "accept-sugg") {
    return accept_suggestion(speaker, previous, rng);
  }
  if (intent == "inform") {
    return inform_relayed_goal(speaker, previous, rng);
  }
  if (intent == "r-confirm" || intent == "r-repet") {
    return query_robot(speaker, intent, previous, rng);
  }
  Draft draft;
  if (intent == "give-feedback") {
    const bool helped = !last_robot_acts_.empty() && last_robot_acts_.front().intent != "cant-help";
    draft.acts.push_back(DialogueAct::from_path(intent, {helped ? "positive" : "negative"}));
  } else if (intent == "change-volume") {
    draft.acts.push_back(DialogueAct::from_path(intent, {"turn_up"}));
    draft.to_other = 0;
  } else if (intent != kNoIntent) {
    draft.acts.push_back(bare(intent));
  }
  return draft;
}

Utterance& UserSimulation::append(std::vector<Utterance>& transcript, size_t speaker, Draft draft,
                                  std::vector<std::string> addressees, core::Rng& rng) {
  Utterance u;
  u.turn = static_cast<int>(transcript.size());
  u.speaker = humans_[speaker].role;
  u.addressees = std::move(addressees);
  u.acts = std::move(draft.acts);
  u.goals = std::move(draft.goals);
  u.text = nlg_.realise(false, u.acts, rng);
  u.start_s = transcript.empty() ? 0.0 : timing_.next_start(transcript.back().end_s, rng);
  u.end_s = u.start_s + timing_.duration(u.text);
  u.heard = errors_.apply(u, config_.roles, rng);
  transcript.push_back(std::move(u));
  return transcript.back();
}

void UserSimulation::respond(std::vector<Utterance>& transcript, core::Rng& rng) {
  if (std::all_of(humans_.begin(), humans_.end(), [](const HumanAgent& h) { return h.left; })) {
    return;
  }
  size_t speaker =
      transcript.empty() ? rng.uniform_index(humans_.size()) : pick_responder(transcript, rng);
  for (unsigned run = 0; run < config_.max_human_run; ++run) {
    const Utterance* previous = transcript.empty() ? nullptr : &transcript.back();
    const std::string intent = context_row(speaker, previous).sample(rng);
    Draft draft = realise(speaker, intent, previous, rng);
    const int other = other_human(speaker);
    bool to_other = draft.to_other == 1;
    if (draft.to_other < 0) {
      to_other = other >= 0 && rng.bernoulli(role_models_[speaker]->to_other_probability(intent));
    }
    to_other = to_other && other >= 0;
    std::vector<std::string> addressees{to_other ? humans_[other].role : std::string(kRobot)};
    const Utterance& said = append(transcript, speaker, std::move(draft), addressees, rng);
    if (to_other) {
      speaker = static_cast<size_t>(other);
      continue;
    }
    last_addresser_ = static_cast<int>(speaker);
    if (humans_[speaker].left || finished() || !addressed_to_robot(said) ||
        !rng.bernoulli(role_models_[speaker]->keep_floor)) {
      break;
    }
  }
}

void UserSimulation::open(std::vector<Utterance>& transcript, core::Rng& rng) {
  respond(transcript, rng);
}

void UserSimulation::farewell(std::vector<Utterance>& transcript, core::Rng& rng) {
  const int responder = last_addresser_ >= 0 && !humans_[last_addresser_].left
                            ? last_addresser_
                            : other_human(humans_.size());
  if (responder < 0 || !rng.bernoulli(config_.farewell_probability)) {
    return;
  }
  Draft draft;
  draft.acts.push_back(bare("bye"));
  humans_[responder].left = true;
  append(transcript, static_cast<size_t>(responder), std::move(draft), {kRobot}, rng);
}

}  // namespace ari_social_sim::dialogue
