#pragma once

#include <map>
#include <vector>

#include "ari_social_sim/core/rng.hpp"
#include "ari_social_sim/model/object_id.hpp"

namespace ari_social_sim::world {

class Simulation;

/// Gaze shares and timing of people in a conversation (docs/world.md "Conversation", cited in
/// docs/references.md). Shares are chances per gaze event; with exponential dwells they are
/// also shares of time.
struct ConversationGazeShares {
  /// A listener looks at the speaker; at another participant; the rest away. 0.80 of the time at
  /// the speaker is 0.88 of the time spent looking at someone, Vertegaal et al. (2001)'s share
  /// for the person listened to.
  double listener_at_speaker{0.80};
  double listener_at_other{0.11};
  /// A speaker looks at the addressee; at another participant; the rest away. With the look at
  /// the addressee as the utterance ends, the addressee gets about 0.77 of the time spent looking
  /// at someone, Vertegaal et al. (2001)'s share for the person spoken to.
  double speaker_at_addressee{0.62};
  double speaker_at_other{0.27};
  /// A speaker looks away as a turn begins (Kendon 1967), for a mean of this many seconds.
  double speaker_look_away_at_start{0.6};
  double look_away_mean_s{1.0};
  /// Mean dwell (s) of one gaze event.
  double mean_dwell_s{2.0};
  /// Chance a listener turns to the next speaker before that speaker starts, and how far ahead
  /// (s, uniform up to this) (Holler & Kendrick 2015).
  double anticipate_next_speaker{0.5};
  double anticipation_lead_max_s{0.6};
  /// A speaker looks at the addressee this many seconds before the utterance ends (Kendon 1967).
  double end_of_turn_look_s{0.6};
};

/// Who holds the floor, as the gaze of the others follows it.
struct GazeRoles {
  model::ObjectId speaker{model::kNoObject};    // none: a silence
  model::ObjectId addressee{model::kNoObject};  // none: the whole group
  double utterance_start_s{0.0};
  double utterance_end_s{0.0};
};

/// The gaze of a conversation group's members while the group talks: listeners follow the
/// speaker, speakers look away as they begin and at their addressee, listeners anticipate the
/// next speaker. In a silence each member's own gaze model (GazeGenerator, the idle behaviour)
/// takes over. The gaze is handed to each member (Human::set_conversation_gaze); a reaction to
/// ARI still overrides it (curious people keep looking at ARI).
class ConversationGaze {
 public:
  explicit ConversationGaze(core::Rng rng) : rng_(rng) {}

  /// `participants`: the members, then ARI if it takes part; members are those that are humans.
  void step(Simulation& simulation, const std::vector<model::ObjectId>& participants,
            const GazeRoles& roles, double now_s);
  /// A member turns to `target` at `at_s`, ahead of that person's turn.
  void anticipate(model::ObjectId member, model::ObjectId target, double at_s);
  /// Hands every member's gaze back to their own model.
  void release(Simulation& simulation);
  const ConversationGazeShares& shares() const { return shares_; }

 private:
  struct State {
    model::ObjectId target{model::kNoObject};
    double away_rad{0.0};  // relative to the body, when looking at nobody
    double since_s{0.0};
    double next_change_s{0.0};
    model::ObjectId speaker_seen{model::kNoObject};
    bool end_look_done{false};
    model::ObjectId anticipated{model::kNoObject};
    double anticipate_at_s{0.0};
  };

  void update(State& state, model::ObjectId member, const std::vector<model::ObjectId>& others,
              const GazeRoles& roles, double now_s);
  // A gaze event: at `focus` (the speaker, or the addressee) with chance at_focus, at another of
  // `others` with at_other, else away.
  void draw(State& state, const std::vector<model::ObjectId>& others, model::ObjectId focus,
            double at_focus, double at_other);
  void look(State& state, model::ObjectId target, double now_s);

  core::Rng rng_;
  ConversationGazeShares shares_;
  std::map<model::ObjectId, State> states_;
  std::vector<model::ObjectId> others_;      // scratch
  std::vector<model::ObjectId> bystanders_;  // scratch
};

}  // namespace ari_social_sim::world
