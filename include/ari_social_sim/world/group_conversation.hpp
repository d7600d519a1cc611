#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "ari_social_sim/core/rng.hpp"
#include "ari_social_sim/model/object_id.hpp"
#include "ari_social_sim/world/conversation_gaze.hpp"
#include "ari_social_sim/world/conversation_lines.hpp"
#include "ari_social_sim/world/conversation_spec.hpp"
#include "ari_social_sim/world/object.hpp"

namespace ari_social_sim::world {

class GroupNavigation;
class SpeechGenerator;

/// The floor of a conversation as the world knows it after a step: what a turn-taking policy
/// needs (who speaks, to whom, when the utterance ends) and what the world state publishes.
struct ConversationFloor {
  model::ObjectId speaker{model::kNoObject};    ///< holding the floor; none in a silence
  model::ObjectId addressee{model::kNoObject};  ///< none: the whole group
  LineKind kind{LineKind::kStatement};          ///< of the speaker's utterance, if a member's
  /// Sim times (s) the current (or last) utterance began and ends: its end is the
  /// transition-relevance place.
  double utterance_start_s{0.0};
  double utterance_end_s{0.0};
  /// The members leave ARI the floor until this time (s), after addressing it; 0 otherwise.
  double robot_floor_until_s{0.0};
};

/// Counts a conversation keeps about ARI in it (docs/world.md "Conversation").
struct RobotTurnCounts {
  uint32_t interruptions{0};  ///< ARI began speaking while a member's utterance had > 0.5 s left
  uint32_t questions{0};      ///< members' questions to ARI
};

/// One group's conversation (issue 31): a turn-taking model after Sacks, Schegloff & Jefferson
/// (1974). At the end of each utterance (its transition-relevance place) the speaker either goes
/// on after a pause, or the addressee of a question answers, or a listener self-selects; the next
/// start is offset from the end by a draw from the published distribution of turn transitions
/// (ConversationSpec), so gaps and overlaps both occur; a lapse sometimes leaves a silence.
/// Listeners backchannel, saying "mm-hm", nodding, or both; rarely two start at once and the later
/// drops out. Utterances are spoken word by word through each member's SpeechGenerator, so
/// everything that hears the world hears them. ARI, while the formation counts it, is a participant
/// whose speech the conversation only observes: members look at it, answer it, ask it questions and
/// leave it the floor, and stop or talk on when it interrupts. Speech the conversation did not
/// start (a script, /sim/say) takes the floor the same way. Everything is drawn from the group's
/// own generators.
class GroupConversation {
 public:
  /// `rng` draws the turn-taking and gaze, `nod_rng` the listeners' nods, so that nodding more
  /// or less leaves the talk as it was.
  GroupConversation(model::ObjectId group_id, const ConversationSpec& spec, core::Rng rng,
                    core::Rng nod_rng);

  /// One step, after the group script: observes who speaks, starts and stops members' speech and
  /// sets their gaze. `lines` gives the words; without it the group stays silent.
  void step(const StepContext& context, const GroupNavigation& group,
            const ConversationLines* lines);
  /// Stops the conversation (switched off, or the group is dropped): the members' gaze returns
  /// to their own models; what they are saying is left to finish.
  void release(Simulation& simulation);

  model::ObjectId group_id() const { return group_id_; }
  const ConversationSpec& spec() const { return spec_; }
  const ConversationFloor& floor() const { return floor_; }
  const RobotTurnCounts& robot_counts() const { return robot_counts_; }
  /// Nods the listeners have made so far.
  uint32_t nods() const { return nods_; }

 private:
  // Something planned for a member at a sim time.
  struct Event {
    enum class Kind { kStart, kBackchannel, kNod, kDropOut };
    Kind kind{Kind::kStart};
    double at_s{0.0};
    model::ObjectId member{model::kNoObject};
    LineKind line{LineKind::kStatement};  // kAnswer: answers `addressee`; else chosen at start
    model::ObjectId addressee{model::kNoObject};
    bool drops_out{false};  // a simultaneous start that gives way
  };

  void update_participants(const GroupNavigation& group);
  bool is_participant(model::ObjectId id) const;
  // Utterances begun by ARI or from outside (a script, /sim/say) take the floor.
  void observe_speakers(const StepContext& context, double now_s);
  void take_floor_from_outside(const StepContext& context, model::ObjectId speaker,
                               const SpeechGenerator& speech, double now_s);
  void run_due_events(const StepContext& context, const ConversationLines& lines, double now_s);
  void start_utterance(const StepContext& context, const ConversationLines& lines,
                       SpeechGenerator& speech, const Event& event);
  void say(SpeechGenerator& speech, model::ObjectId member, const ConversationLine& line,
           double start_s);
  // A line of `kind`, led by small talk until it has about `words` words.
  ConversationLine compose(const ConversationLines& lines, LineKind kind,
                           const std::string& addressee_name, int words);
  // Plans what follows an utterance of `speaker` from `start_s` to `end_s`: backchannels, and
  // the answer, the speaker's next utterance after a pause, or a self-selected next speaker.
  void plan_after(model::ObjectId speaker, double start_s, double end_s);
  void plan_backchannels(model::ObjectId speaker, double start_s, double end_s);
  void plan_nod(model::ObjectId listener, double at_s);
  void nod(Simulation& simulation, model::ObjectId listener, double at_s);
  void plan_self_selection(model::ObjectId previous, double end_s, bool lapse);
  double lapse_mean_or_first(model::ObjectId previous) const;
  // Listeners may turn to `next` ahead of its start at `at_s`.
  void anticipate_turn(model::ObjectId next, double at_s);
  // What kind of line the member starting `event` says, and to whom.
  std::pair<LineKind, model::ObjectId> choose_line(model::ObjectId speaker, const Event& event);
  model::ObjectId choose_next_speaker(model::ObjectId previous);
  double transition_offset_s(double utterance_s);
  int utterance_words();
  void insert_event(const Event& event);

  model::ObjectId group_id_;
  ConversationSpec spec_;
  core::Rng rng_;
  core::Rng nod_rng_;
  std::vector<model::ObjectId> members_;  // as of this step, in the group's order
  model::ObjectId robot_{model::kNoObject};
  std::vector<model::ObjectId> participants_;        // the members, then ARI while it takes part
  std::map<model::ObjectId, double> talkativeness_;  // seeded per member: floor shares differ
  std::map<model::ObjectId, double> started_s_;      // start of each speaker's last utterance seen
  std::vector<Event> events_;                        // ordered by time
  ConversationFloor floor_;
  model::ObjectId previous_speaker_{model::kNoObject};
  double last_end_s_{0.0};
  model::ObjectId yielded_to_robot_{model::kNoObject};  // resumes after ARI
  bool robot_asked_since_it_spoke_{false};
  RobotTurnCounts robot_counts_;
  uint32_t nods_{0};
  ConversationGaze gaze_;
};

}  // namespace ari_social_sim::world
