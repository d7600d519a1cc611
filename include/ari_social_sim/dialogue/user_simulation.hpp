#pragma once

#include <string>
#include <vector>

#include "ari_social_sim/core/config_fields.hpp"
#include "ari_social_sim/core/rng.hpp"
#include "ari_social_sim/dialogue/agenda.hpp"
#include "ari_social_sim/dialogue/domain.hpp"
#include "ari_social_sim/dialogue/error_model.hpp"
#include "ari_social_sim/dialogue/nlg.hpp"
#include "ari_social_sim/dialogue/turn_timing.hpp"
#include "ari_social_sim/dialogue/user_model.hpp"
#include "ari_social_sim/dialogue/utterance.hpp"

namespace ari_social_sim::dialogue {

/// Behaviour knobs of the simulated humans that the corpus does not pin down.
struct UserSimulationConfig {
  std::vector<std::string> roles{"patient", "companion"};
  unsigned min_patience{3};  // PyDial's benchmark: 4-6 turns
  unsigned max_patience{5};
  unsigned max_asks{3};
  unsigned max_human_run{6};
  double reask_probability{0.7};
  double farewell_probability{0.5};

  template <class V>
  void visit(V& v) {
    v.field("roles", roles, "one simulated human per role, each with its user model table");
    v.rule("roles", bad_role().empty(), "at least one role, each named, distinct and not ARI",
           bad_role());
    v.field("min_patience", min_patience, "bad robot answers a human tolerates, at least",
            core::positive());
    v.field("max_patience", max_patience, "... and at most (drawn per dialogue)", core::positive());
    v.rule("max_patience", min_patience <= max_patience,
           "an integer >= min_patience (" + std::to_string(min_patience) + ")",
           std::to_string(max_patience));
    v.field("max_asks", max_asks, "statements of one goal to ARI before it counts as failed",
            core::positive());
    v.field("max_human_run", max_human_run, "human utterances in a row before ARI gets the floor",
            core::positive());
    v.field("reask_probability", reask_probability,
            "P(re-asking an unanswered goal rather than moving on)", core::between(0.0, 1.0));
    v.field("farewell_probability", farewell_probability, "P(a human answers ARI's bye)",
            core::between(0.0, 1.0));
  }

  /// Throws core::ConfigError naming the field (no roles, a role twice, min > max patience, ...).
  void validate() const;

 private:
  /// "[]" without roles; else the first role that is empty, ARI's name or a repeat, quoted; "".
  std::string bad_role() const;
};

/// One simulated human.
struct HumanAgent {
  std::string role;
  int patience{0};
  bool left{false};  ///< said bye
};

/// The simulated humans of one dialogue: goals in agendas and a shared pool, responses drawn from
/// the fitted P(user act | context) per role, goals stated to ARI or to the other human, relayed
/// or answered by the other human, patience, turn-taking with gaps, NLG and the error layer.
/// Holds references to constant parts that must outlive it.
class UserSimulation {
 public:
  /// Throws core::ConfigError when the model lacks a table for a configured role.
  UserSimulation(UserSimulationConfig config, const Domain& domain, const UserModel& model,
                 const std::string& model_source, const Nlg& nlg, const ErrorModel& errors,
                 const TurnTiming& timing);

  /// New goals and humans; the transcript is the caller's.
  void reset(core::Rng& rng);
  /// The humans speak first (ARI did not open the dialogue).
  void open(std::vector<Utterance>& transcript, core::Rng& rng);
  /// Updates goals and patience from ARI's utterance (the last of `transcript`) and labels the
  /// goals it answers (AG).
  void hear_robot(Utterance& robot);
  /// The humans' turn after ARI's utterance or, when the last utterance is a human's, after ARI
  /// stayed silent. Appends at least one utterance unless every human has left.
  void respond(std::vector<Utterance>& transcript, core::Rng& rng);
  /// Reply to ARI's bye: one human says bye with P = farewell_probability.
  void farewell(std::vector<Utterance>& transcript, core::Rng& rng);

  /// Replaces the sampled goals (scripted scenarios, tests); call after reset.
  void set_agenda(Agenda agenda) { agenda_ = std::move(agenda); }

  /// Every goal is resolved, closed or failed, or every human has left.
  bool finished() const;
  const Agenda& agenda() const { return agenda_; }
  const std::vector<HumanAgent>& humans() const { return humans_; }
  const UserSimulationConfig& config() const { return config_; }

 private:
  struct Draft {
    std::vector<DialogueAct> acts;
    std::vector<GoalLabel> goals;
    int to_other{-1};  ///< -1: decide from the model; 0: to ARI; 1: to the other human
  };

  size_t pick_responder(const std::vector<Utterance>& transcript, core::Rng& rng) const;
  const IntentDistribution& context_row(size_t speaker, const Utterance* previous) const;
  Draft realise(size_t speaker, const std::string& intent, const Utterance* previous,
                core::Rng& rng);
  // One per intent that touches the agenda or refers back to an earlier turn; an intent that
  // cannot be said in context falls back to a plainer one through realise().
  Draft state_goal(size_t speaker, const Utterance* previous, core::Rng& rng);
  Draft thank_and_close(size_t speaker, const std::string& intent);
  Draft say_bye(size_t speaker, const Utterance* previous, core::Rng& rng);
  Draft suggest_goal(size_t speaker, core::Rng& rng);
  Draft accept_suggestion(size_t speaker, const Utterance* previous, core::Rng& rng);
  Draft inform_relayed_goal(size_t speaker, const Utterance* previous, core::Rng& rng);
  Draft query_robot(size_t speaker, const std::string& intent, const Utterance* previous,
                    core::Rng& rng);
  bool said_by_other_human(size_t speaker, const Utterance* previous) const;
  Draft close_or_leave(size_t speaker);
  int other_human(size_t speaker) const;
  void penalise(int goal_index);
  Utterance& append(std::vector<Utterance>& transcript, size_t speaker, Draft draft,
                    std::vector<std::string> addressees, core::Rng& rng);

  UserSimulationConfig config_;
  const Domain& domain_;
  const UserModel& model_;
  std::vector<const RoleModel*> role_models_;
  const Nlg& nlg_;
  const ErrorModel& errors_;
  const TurnTiming& timing_;

  Agenda agenda_;
  std::vector<HumanAgent> humans_;
  int last_addresser_{-1};  ///< human who last spoke to ARI
  int relay_goal_{-1};      ///< goal stated to the other human, waiting to be relayed or answered
  std::vector<DialogueAct> last_robot_acts_;
};

}  // namespace ari_social_sim::dialogue
