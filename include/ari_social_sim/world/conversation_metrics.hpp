#pragma once

#include <map>
#include <vector>

#include "ari_social_sim/world/world_snapshot.hpp"

namespace ari_social_sim::world {

/// What one run's conversations did (docs/world.md "Conversation"), from the world's states alone,
/// so that a live run's bag measures as the engine does.
struct ConversationSummary {
  /// Offsets (s) of turn transitions: from the end of one speaker's utterance to the start of the
  /// next speaker's, negative in overlap; in the order they happened.
  std::vector<double> transition_offsets_s;
  double overlap_share{0.0};  // of the transitions
  double offset_median_s{0.0};
  double offset_mode_s{0.0};  // centre of the fullest 100 ms bin
  /// Turns (utterances by a speaker other than the previous one) per minute of conversation.
  double turns_per_minute{0.0};
  /// Listeners' gaze while one participant speaks: share of the time at the speaker, and share of
  /// the time spent looking at a participant that goes to the speaker.
  double listener_gaze_at_speaker{0.0};
  double listener_people_gaze_at_speaker{0.0};
  /// A speaker's gaze while addressing one person: the share at the addressee, of all the time and
  /// of the time spent looking at a participant.
  double speaker_gaze_at_addressee{0.0};
  double speaker_people_gaze_at_addressee{0.0};
  /// Share of all speaking time (backchannels aside) per participant, ARI included.
  std::map<model::ObjectId, double> floor_share;
  /// ARI's utterances begun while a member held the floor with more than 0.5 s of an utterance
  /// left (GroupConversation's interruption).
  int robot_interruptions{0};
  /// Seconds from ARI first taking part in a talking group to a member first addressing it;
  /// negative when no member did.
  double robot_addressed_after_s{-1.0};
  /// Whether ARI first took part in a talking group while no member held the floor: 1 in a
  /// pause, 0 over a member's utterance, -1 when it never took part.
  int robot_entered_in_pause{-1};
};

/// The figures an episode reports of its talking groups and of ARI in them: run_episodes' CSV
/// columns and the join_conversation task's info, under the same names.
struct ConversationFigures {
  int turn_transitions{0};               // changes of speaker in all talking groups
  double overlap_share{0.0};             // of those, the share that began in overlap
  double listener_gaze_at_speaker{0.0};  // share of listeners' gaze at people on the speaker
  double ari_floor_share{0.0};           // ARI's share of the groups' speaking time
  int ari_interruptions{0};              // ARI began talking over a member's utterance
  /// s from ARI first taking part in a talking group to a member addressing it; -1: never.
  double ari_addressed_after_s{-1.0};
  /// 1: ARI first took part in a talking group in a pause; 0: over a member's utterance; -1: never.
  int ari_entered_in_pause{-1};

  /// The figures of `summary`, with `ari` the robot's id (kNoObject when there was no ARI).
  static ConversationFigures of(const ConversationSummary& summary, model::ObjectId ari);
};

/// Accumulates ConversationSummary over consecutive world states; states whose time does not
/// advance begin another run (another episode), whose turns are kept apart.
class ConversationMetrics {
 public:
  void observe(const WorldSnapshot& snapshot);
  ConversationSummary summary() const;

 private:
  struct Utterance {
    size_t run{0};
    model::ObjectId group{model::kNoObject};
    model::ObjectId speaker{model::kNoObject};
    double start_s{0.0};
    double end_s{0.0};
  };
  struct Open {
    double start_s{0.0};
    double planned_end_s{0.0};  // unless cut off
    model::ObjectId group{model::kNoObject};
  };
  struct GazeCount {
    double total_s{0.0};
    double at_people_s{0.0};
    double at_target_s{0.0};
  };

  // Closes what the last run left open.
  void close_all();
  void track_speech(model::ObjectId speaker, model::ObjectId group, const SpeechSnapshot& speech,
                    double now_s);
  void count_gaze(const WorldSnapshot& snapshot, const GroupSnapshot& group, double dt_s);
  void follow_robot(const WorldSnapshot& snapshot, const GroupSnapshot& group);

  std::map<model::ObjectId, Open> open_;  // utterances in progress by speaker
  std::vector<Utterance> utterances_;
  std::map<model::ObjectId, double> speaking_s_;
  double conversation_s_{0.0};  // summed over groups
  GazeCount listeners_;
  GazeCount speakers_;
  double last_time_s_{-1.0};
  struct Floor {
    model::ObjectId speaker{model::kNoObject};
    double utterance_end_s{0.0};
  };
  std::map<model::ObjectId, Floor> last_floor_;  // each group's floor in the last step
  double robot_joined_s_{-1.0};
  double robot_last_start_s_{-1.0};
  int robot_interruptions_{0};
  double robot_addressed_after_s_{-1.0};
  int robot_entered_in_pause_{-1};
  size_t run_{0};
};

}  // namespace ari_social_sim::world
