#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "ari_social_sim/scenario/commands.hpp"
#include "ari_social_sim/scenario/conversation.hpp"
#include "ari_social_sim/scenario/heard_lines.hpp"
#include "ari_social_sim/scenario/observations.hpp"
#include "ari_social_sim/scenario/scenario.hpp"
#include "ari_social_sim/scenario/transcript.hpp"

namespace ari_social_sim::scenario {

/// How a run ended.
struct Outcome {
  bool success{false};
  std::string reason;       // the stop action's reason, or why the run failed
  std::string final_state;  // the state the run ended in; empty if the script had not started
  double end_time_s{0.0};   // sim time since the script started
  bool interrupted{false};  // stopped from outside (SIGINT, shutdown): neither success nor failure
};

/// One entry into a state, and the re-entries that followed it without leaving: a state whose
/// transition leads back to itself (a polling loop) is one visit, however often it loops.
struct StateVisit {
  std::string state;
  double enter_s{0.0};  // sim time since the script started
  size_t entries{1};
};

/// Plays a scenario's script (D6.4's Script.step, §3.7, as a state machine) against any run
/// that provides Observations and Commands: scenario_node over ROS, the batch tool in-process.
/// Each tick it records what was said, ends the run at the time limit, and fires at most one
/// transition of the current state (the first whose conditions all hold): its actions, then the
/// next state's entry actions. A refused command ends the run as a failure naming the state and
/// the action. approach and join_group name the human by the person id perception reports it
/// under (Observations::person_ids); for a human not matched with any person yet, ARI's navigation
/// fails with the reason, which the script can react to (navigation_failed). Holds a reference to
/// the scenario, which must outlive it.
class ScriptRunner {
 public:
  /// `seed` draws the random groups and ARI's words when it converses (the scene's seed, or the
  /// episode's in batch runs). `dialogue` is needed by scripts that converse; throws
  /// core::ConfigError when such a script gets none. `hearing` is where ARI's side of `converse`
  /// takes what the people said from.
  ScriptRunner(const Scenario& scenario, uint64_t seed,
               const dialogue::DialogueSetup* dialogue = nullptr,
               Hearing hearing = Hearing::kSimulated);

  /// One tick, with observations at least once per world step. The first call adds the random
  /// groups and enters the start state. Does nothing once the run has ended.
  void update(const Observations& observations, Commands& commands);

  /// Ends the run as a failure from outside the script (scenario_node's wall-time limit, a world
  /// that stopped sending states), at the last tick's time and state. Does nothing once ended.
  void abort(const std::string& reason);
  /// Ends the run as interrupted (`cause`: "SIGINT", ...), likewise.
  void interrupt(const std::string& cause);

  bool finished() const { return outcome_.has_value(); }
  const std::optional<Outcome>& outcome() const { return outcome_; }
  /// Name of the current state; empty until the start state is entered.
  const std::string& state() const;
  /// The states entered, in order; at most kMaxRecordedVisits, then only counted.
  const std::vector<StateVisit>& visits() const { return visits_; }
  /// Visits past kMaxRecordedVisits, not recorded one by one, and when the first of them began.
  size_t unrecorded_visits() const { return unrecorded_visits_; }
  double unrecorded_from_s() const { return unrecorded_from_s_; }
  /// Bounds what a run keeps of a script that alternates between states for hours (every tick a
  /// new visit, megabytes of history): far more than any script meant to finish goes through.
  static constexpr size_t kMaxRecordedVisits = 1000;
  const Transcript& transcript() const { return transcript_; }
  /// How the dialogue with the simulated humans ended, once it has.
  const std::optional<DialogueEnd>& dialogue_end() const { return dialogue_end_; }
  /// Sim time (s) of the first update, from which the script's times count.
  double start_time_s() const { return start_s_; }

 private:
  struct FinishedAct {
    AgentRef speaker;
    std::string act;
  };

  void begin(const Observations& observations, Commands& commands);
  void enter(size_t state, const Observations& observations, Commands& commands);
  void record_visit(const std::string& state);
  bool holds(const Condition& condition, const Observations& observations) const;
  /// Runs actions in order; false once the run has ended (stop or a refused command).
  bool run(const std::vector<Action>& actions, const Observations& observations,
           Commands& commands);
  /// ARI approaches a human, or joins its group, through the person perception reports it as.
  void approach(model::ObjectId human, bool join_group, const Observations& observations,
                Commands& commands);
  void end(bool success, const std::string& reason);
  /// Labels ARI's new transcript lines with the acts the script gave their texts.
  void label_ari_lines();

  const Scenario& scenario_;
  uint64_t seed_;
  bool started_{false};
  double start_s_{0.0};
  double now_s_{0.0};  // sim time since the script started, of the current tick
  size_t state_{0};
  double state_enter_s_{0.0};
  std::vector<FinishedAct> finished_in_state_;  // utterances that ended since entering the state
  HeardLines heard_lines_;
  std::vector<std::string> heard_in_state_;  // acts ARI heard since entering the state
  bool not_understood_in_state_{false};      // and words it took for no line
  bool addressed_in_state_{false};           // a member spoke to ARI since entering the state
  std::vector<SayAction> ari_says_;  // ARI's utterances asked for and not yet heard, in order
  size_t lines_labelled_{0};
  std::vector<StateVisit> visits_;
  size_t unrecorded_visits_{0};
  double unrecorded_from_s_{0.0};
  Transcript transcript_;
  std::optional<Conversation> conversation_;  // when the runner has the dialogue setup
  std::optional<DialogueEnd> dialogue_end_;
  std::optional<Outcome> outcome_;
};

/// A short description of an action for messages, e.g. `say (ARI, QUESTION:HELP)`.
std::string describe(const Action& action);

}  // namespace ari_social_sim::scenario
