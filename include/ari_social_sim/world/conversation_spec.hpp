#pragma once

#include "ari_social_sim/core/config_fields.hpp"

namespace ari_social_sim::world {

/// Longest wait (s) a conversation parameter may name: beyond a minute a group has stopped talking.
constexpr double kMaxConversationWaitS = 60.0;

/// How a conversation group talks (docs/world.md "Conversation"): the turn-taking model's
/// distributions, each from published studies of conversation (docs/references.md) unless noted.
struct ConversationSpec {
  /// Off: the group stands silent unless a script or /sim/say makes someone speak.
  bool enabled{true};
  /// Words of one utterance: log-normal with this median and log-spread. Six words at 150 words
  /// a minute is 2.4 s, near the mean turn of about 2 s of Levinson & Torreira (2015).
  double utterance_words_median{6.0};
  double utterance_words_log_spread{0.5};
  /// Offset (s) from the end of one speaker's utterance to the start of the next speaker's,
  /// negative in overlap: an asymmetric Laplace distribution, sharp at its mode and with
  /// exponential sides, early (overlaps) and late (gaps), as real offsets are. A mode of 150 ms,
  /// sides of 0.35 s and 0.45 s give a mean of 250 ms, a median near 200 ms (Stivers et al. 2009:
  /// modes 0-200 ms in ten languages, English mean 236 ms) and about a third of the transitions
  /// in overlap (Heldner & Edlund 2010: 40-45 %).
  double transition_offset_mode_s{0.15};
  double transition_offset_early_s{0.35};
  double transition_offset_late_s{0.45};
  /// Chance the speaker keeps the floor for another utterance after a pause within the turn,
  /// and the pause's median (s, log-normal, log-spread 0.5): pauses are longer than gaps
  /// (Heldner & Edlund 2010).
  double hold_probability{0.2};
  double pause_median_s{0.6};
  /// Chance an utterance to one person is a question, which selects that person as next speaker
  /// (Sacks, Schegloff & Jefferson 1974, rule 1a); otherwise the next speaker self-selects.
  double question_probability{0.3};
  /// Chance each listener says a backchannel ("mm-hm") during an utterance of 1.5 s or more.
  double backchannel_probability{0.25};
  /// Nods, the backchannels without words: the chance each listener nods (apart from any "mm-hm")
  /// during such an utterance, and the chance an "mm-hm" comes with a nod. Knight (2009) counted
  /// 72 listener nods alone and 44 with a spoken backchannel in her case study: 0.2 and 0.5 give
  /// the same share of nods alone (0.62).
  double nod_probability{0.2};
  double nod_with_backchannel_probability{0.5};
  /// Chance that nobody takes the floor at a transition point, and the mean (s, exponential) of
  /// the lapse that follows: the silences a newcomer can enter in.
  double lapse_probability{0.1};
  double lapse_mean_s{2.0};
  /// Chance each other listener starts at the same transition as the next speaker; the later
  /// starter drops out within two words (Schegloff 2000). Our choice: no corpus gives the rate.
  double simultaneous_start_probability{0.05};
  /// While ARI takes part: the chance a member's utterance is a question to ARI from the dialogue
  /// domain, and how long (s) the members leave ARI the floor before one of them goes on (after
  /// their question, and after each line of an exchange with ARI from outside).
  double robot_question_probability{0.3};
  double robot_floor_wait_s{4.0};
  /// Chance a member ARI talks over stops at once (yields); otherwise the member finishes the
  /// utterance (talks on).
  double yield_to_robot_probability{0.6};

  template <class V>
  void visit(V& v) {
    const core::Bounds share = core::between(0.0, 1.0);
    const core::Bounds wait = {0.0, kMaxConversationWaitS, true};
    v.field("enabled", enabled, "whether the group talks on its own");
    v.field("utterance_words_median", utterance_words_median, "words, median of an utterance",
            core::between(1.0, 100.0));
    v.field("utterance_words_log_spread", utterance_words_log_spread,
            "log-spread of the words of an utterance", core::between(0.0, 2.0));
    v.field("transition_offset_mode", transition_offset_mode_s,
            "s, most likely offset from one speaker's end to the next one's start (negative: "
            "overlap)",
            core::between(-2.0, 5.0));
    v.field("transition_offset_early", transition_offset_early_s,
            "s, mean distance of offsets before the mode (the overlapping side)",
            core::between(0.0, 5.0));
    v.field("transition_offset_late", transition_offset_late_s,
            "s, mean distance of offsets after the mode (the gap side)", core::between(0.0, 5.0));
    v.field("hold_probability", hold_probability, "chance the speaker goes on after a pause",
            share);
    v.field("pause_median", pause_median_s, "s, median pause within a turn", wait);
    v.field("question_probability", question_probability,
            "chance an utterance to one person asks them, selecting them as next speaker", share);
    v.field("backchannel_probability", backchannel_probability,
            "chance each listener backchannels during an utterance", share);
    v.field("nod_probability", nod_probability,
            "chance each listener nods (without words) during an utterance", share);
    v.field("nod_with_backchannel_probability", nod_with_backchannel_probability,
            "chance a listener's \"mm-hm\" comes with a nod", share);
    v.field("lapse_probability", lapse_probability,
            "chance nobody takes the floor at a transition point", share);
    v.field("lapse_mean", lapse_mean_s, "s, mean silence of a lapse", wait);
    v.field("simultaneous_start_probability", simultaneous_start_probability,
            "chance each other listener starts together with the next speaker", share);
    v.field("robot_question_probability", robot_question_probability,
            "chance a member's utterance asks ARI, while ARI takes part", share);
    v.field("robot_floor_wait", robot_floor_wait_s,
            "s, how long the members leave ARI the floor after addressing it", wait);
    v.field("yield_to_robot_probability", yield_to_robot_probability,
            "chance a member ARI talks over stops at once", share);
  }
};

}  // namespace ari_social_sim::world
