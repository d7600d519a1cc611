#include "ari_social_sim/world/group_conversation.hpp"

#include <algorithm>
#include <cmath>

#include "ari_social_sim/world/group_navigation.hpp"
#include "ari_social_sim/world/simulation.hpp"
#include "ari_social_sim/world/speech_generator.hpp"

namespace ari_social_sim::world {
namespace {

// ARI talks over a member when it starts with more than this (s) of the member's utterance left.
constexpr double kInterruptionMarginS = 0.5;
// A simultaneous start comes this much (s, uniform) after the next speaker's; the later starter
// drops out after this many seconds (uniform): one or two words (Schegloff 2000).
constexpr double kSimultaneousWindowS = 0.2;
constexpr double kDropOutMinS = 0.3;
constexpr double kDropOutMaxS = 0.8;
// A silence longer than this (s) hands each member's gaze back to their own model.
constexpr double kIdleAfterS = 1.0;
// The first utterance of a group comes within this many seconds (uniform) of its forming.
constexpr double kFirstStartMaxS = 3.0;
// Backchannels fall in this part of an utterance (shares of its length) and only in
// utterances of at least kBackchannelMinUtteranceS.
constexpr double kBackchannelFrom = 0.4;
constexpr double kBackchannelTo = 0.85;
constexpr double kBackchannelMinUtteranceS = 1.5;
// A nod dips the head 1-3 times, each dip 0.3-0.5 s long and 6-14 deg deep: our choice, as
// the nods seen in conversation video, for want of published kinematics.
constexpr int kMaxNodCycles = 3;
constexpr double kNodCycleS[2] = {0.3, 0.5};
constexpr double kNodAmplitudeRad[2] = {0.10, 0.24};
// An overlap covers at most this share of the utterance it overlaps.
constexpr double kMaxOverlapShare = 0.5;
// Addressee choice in groups of three or more: the whole group, else the previous speaker.
constexpr double kAddressGroup = 0.3;
constexpr double kAddressPreviousSpeaker = 0.45;
// Lines put before the final one to reach an utterance's drawn length.
constexpr int kMaxLeadingLines = 3;
// Spread of the members' talkativeness (log-normal), which makes floor shares differ.
constexpr double kTalkativenessLogSpread = 0.5;
// The one who yielded to ARI is this much likelier to speak first after it.
constexpr double kResumeWeight = 4.0;

std::string name_of(const Simulation& simulation, model::ObjectId id) {
  if (id == model::kNoObject) {
    return "";
  }
  const Human* human = simulation.find_human(id);
  return human != nullptr ? human->spec().name : "ARI";
}

}  // namespace

GroupConversation::GroupConversation(model::ObjectId group_id, const ConversationSpec& spec,
                                     core::Rng rng, core::Rng nod_rng)
    : group_id_(group_id),
      spec_(spec),
      rng_(rng),
      nod_rng_(nod_rng),
      gaze_(core::Rng(rng_.next_u64())) {}

void GroupConversation::step(const StepContext& context, const GroupNavigation& group,
                             const ConversationLines* lines) {
  const double now_s = context.time_s + context.dt_s;
  update_participants(group);
  if (lines == nullptr || participants_.size() < 2) {
    events_.clear();
    floor_ = {};
    gaze_.release(context.simulation);
    return;
  }
  observe_speakers(context, now_s);
  run_due_events(context, *lines, now_s);
  const bool start_planned = std::any_of(events_.begin(), events_.end(), [](const Event& e) {
    return e.kind == Event::Kind::kStart && !e.drops_out;
  });
  if (floor_.speaker == model::kNoObject && !start_planned && now_s >= floor_.robot_floor_until_s) {
    floor_.robot_floor_until_s = 0.0;
    plan_self_selection(previous_speaker_, now_s, previous_speaker_ == model::kNoObject);
  }
  const bool silent_long = floor_.speaker == model::kNoObject && now_s - last_end_s_ > kIdleAfterS;
  if (silent_long || previous_speaker_ == model::kNoObject) {
    gaze_.release(context.simulation);
    return;
  }
  const model::ObjectId focus =
      floor_.speaker != model::kNoObject ? floor_.speaker : previous_speaker_;
  gaze_.step(context.simulation, participants_,
             {focus, floor_.addressee, floor_.utterance_start_s, floor_.utterance_end_s}, now_s);
}

void GroupConversation::release(Simulation& simulation) {
  events_.clear();
  floor_ = {};
  gaze_.release(simulation);
}

void GroupConversation::update_participants(const GroupNavigation& group) {
  members_ = group.members();
  robot_ = group.robot_joining();
  participants_ = members_;
  if (robot_ != model::kNoObject) {
    participants_.push_back(robot_);
  }
  for (model::ObjectId member : members_) {
    if (talkativeness_.count(member) == 0) {
      talkativeness_[member] = std::exp(rng_.normal(0.0, kTalkativenessLogSpread));
    }
  }
  if (floor_.speaker != model::kNoObject && !is_participant(floor_.speaker)) {
    floor_.speaker = model::kNoObject;
  }
}

bool GroupConversation::is_participant(model::ObjectId id) const {
  return id != model::kNoObject &&
         (id == robot_ || std::find(members_.begin(), members_.end(), id) != members_.end());
}

void GroupConversation::observe_speakers(const StepContext& context, double now_s) {
  for (model::ObjectId id : participants_) {
    const SpeechGenerator* speech = context.simulation.mutable_speech(id);
    if (speech == nullptr || !speech->is_speaking()) {
      continue;
    }
    const auto seen = started_s_.find(id);
    if (seen == started_s_.end() || seen->second != speech->start_s()) {
      take_floor_from_outside(context, id, *speech, now_s);
    }
  }
  if (floor_.speaker != model::kNoObject) {
    const SpeechGenerator* speech = context.simulation.mutable_speech(floor_.speaker);
    if (speech == nullptr || !speech->is_speaking()) {
      previous_speaker_ = floor_.speaker;
      floor_.speaker = model::kNoObject;
      last_end_s_ = now_s;
    }
  }
}

void GroupConversation::take_floor_from_outside(const StepContext& context, model::ObjectId speaker,
                                                const SpeechGenerator& speech, double now_s) {
  started_s_[speaker] = speech.start_s();
  events_.clear();
  if (speaker == robot_) {
    robot_asked_since_it_spoke_ = false;
    floor_.robot_floor_until_s = 0.0;
    const SpeechGenerator* member_speech =
        floor_.speaker != model::kNoObject && floor_.speaker != robot_
            ? context.simulation.mutable_speech(floor_.speaker)
            : nullptr;
    if (member_speech != nullptr && member_speech->is_speaking() &&
        member_speech->end_s() > now_s + kInterruptionMarginS) {
      ++robot_counts_.interruptions;
      if (rng_.bernoulli(spec_.yield_to_robot_probability)) {
        context.simulation.mutable_speech(floor_.speaker)->stop(now_s);
        yielded_to_robot_ = floor_.speaker;
      }
    }
  } else {
    // A member made to speak from outside has the floor: whoever else of the group started an
    // utterance of the conversation drops out, as a simultaneous starter does.
    for (model::ObjectId member : members_) {
      SpeechGenerator* other = context.simulation.mutable_speech(member);
      if (member != speaker && other->is_speaking()) {
        other->stop(now_s);
      }
    }
  }
  if (floor_.speaker != model::kNoObject && floor_.speaker != speaker) {
    previous_speaker_ = floor_.speaker;
  }
  floor_.speaker = speaker;
  floor_.addressee = model::kNoObject;
  floor_.kind = LineKind::kStatement;
  floor_.utterance_start_s = speech.start_s();
  floor_.utterance_end_s = speech.end_s();
  // A line from outside while ARI takes part, ARI's own included, is an exchange with ARI (a
  // script's, a dialogue's): the members leave the answer to it, holding back for
  // robot_floor_wait after each of its lines, and talk on their own once it has gone quiet.
  // Only ARI's lines draw backchannels: over a member's line to ARI the others wait for ARI's
  // answer, and ARI's recogniser hears the line alone.
  const bool exchange = robot_ != model::kNoObject;
  if (exchange) {
    floor_.robot_floor_until_s = speech.end_s() + spec_.robot_floor_wait_s;
    if (speaker == robot_) {
      plan_backchannels(speaker, speech.start_s(), speech.end_s());
    }
    return;
  }
  plan_after(speaker, speech.start_s(), speech.end_s());
}

void GroupConversation::run_due_events(const StepContext& context, const ConversationLines& lines,
                                       double now_s) {
  while (!events_.empty() && events_.front().at_s <= now_s + 1e-9) {
    const Event event = events_.front();
    events_.erase(events_.begin());
    SpeechGenerator* speech = context.simulation.mutable_speech(event.member);
    if (speech == nullptr || !is_participant(event.member) || event.member == robot_) {
      continue;
    }
    switch (event.kind) {
      case Event::Kind::kDropOut:
        if (speech->is_speaking() && speech->start_s() == started_s_[event.member]) {
          speech->stop(now_s);
        }
        break;
      case Event::Kind::kBackchannel:
        if (!speech->is_speaking()) {
          say(*speech, event.member, lines.line(LineKind::kBackchannel, "", rng_),
              std::max(event.at_s, context.time_s));
        }
        break;
      case Event::Kind::kNod:
        // A listener nods; one who has started talking meanwhile does not.
        if (!speech->is_speaking() || speech->start_s() >= event.at_s) {
          nod(context.simulation, event.member, std::max(event.at_s, context.time_s));
        }
        break;
      case Event::Kind::kStart:
        start_utterance(context, lines, *speech, event);
        break;
    }
  }
}

void GroupConversation::say(SpeechGenerator& speech, model::ObjectId member,
                            const ConversationLine& line, double start_s) {
  speech.say(line.act, line.content, start_s);
  started_s_[member] = start_s;
}

void GroupConversation::start_utterance(const StepContext& context, const ConversationLines& lines,
                                        SpeechGenerator& speech, const Event& event) {
  const double start_s = std::max(event.at_s, context.time_s);
  const auto [kind, addressee] = choose_line(event.member, event);
  const ConversationLine line =
      compose(lines, kind, name_of(context.simulation, addressee), utterance_words());
  say(speech, event.member, line, start_s);
  if (event.drops_out) {
    insert_event(
        {Event::Kind::kDropOut, start_s + rng_.uniform(kDropOutMinS, kDropOutMaxS), event.member});
    return;
  }
  if (floor_.speaker != model::kNoObject && floor_.speaker != event.member) {
    previous_speaker_ = floor_.speaker;
  }
  floor_.speaker = event.member;
  floor_.addressee = addressee;
  floor_.kind = kind;
  floor_.utterance_start_s = start_s;
  floor_.utterance_end_s = speech.end_s();
  if (kind == LineKind::kRobotQuestion) {
    ++robot_counts_.questions;
    robot_asked_since_it_spoke_ = true;
  }
  plan_after(event.member, start_s, speech.end_s());
}

ConversationLine GroupConversation::compose(const ConversationLines& lines, LineKind kind,
                                            const std::string& addressee_name, int words) {
  ConversationLine last = lines.line(kind, addressee_name, rng_);
  size_t count = spoken_words(last.content).size();
  for (int i = 0; i < kMaxLeadingLines && static_cast<int>(count) < words; ++i) {
    const ConversationLine lead = lines.line(LineKind::kStatement, addressee_name, rng_);
    last.act = lead.act + "; " + last.act;
    last.content = lead.content + " " + last.content;
    count += spoken_words(lead.content).size();
  }
  return last;
}

void GroupConversation::plan_after(model::ObjectId speaker, double start_s, double end_s) {
  plan_backchannels(speaker, start_s, end_s);
  const bool member = speaker != robot_;
  if (member && floor_.kind == LineKind::kRobotQuestion) {
    floor_.robot_floor_until_s = end_s + spec_.robot_floor_wait_s;
  } else if (member && floor_.kind == LineKind::kQuestion && is_participant(floor_.addressee)) {
    const double at_s = end_s + transition_offset_s(end_s - start_s);
    anticipate_turn(floor_.addressee, at_s);
    insert_event({Event::Kind::kStart, at_s, floor_.addressee, LineKind::kAnswer, speaker});
  } else if (member && rng_.bernoulli(spec_.hold_probability)) {
    const double pause_s = spec_.pause_median_s * std::exp(rng_.normal(0.0, 0.5));
    insert_event({Event::Kind::kStart, end_s + pause_s, speaker});
  } else {
    plan_self_selection(speaker, end_s, rng_.bernoulli(spec_.lapse_probability));
  }
}

void GroupConversation::plan_backchannels(model::ObjectId speaker, double start_s, double end_s) {
  const double length_s = end_s - start_s;
  if (length_s < kBackchannelMinUtteranceS) {
    return;
  }
  for (model::ObjectId listener : members_) {
    if (listener == speaker) {
      continue;
    }
    if (rng_.bernoulli(spec_.backchannel_probability)) {
      const double at_s = start_s + length_s * rng_.uniform(kBackchannelFrom, kBackchannelTo);
      insert_event({Event::Kind::kBackchannel, at_s, listener});
      if (nod_rng_.bernoulli(spec_.nod_with_backchannel_probability)) {
        plan_nod(listener, at_s);
      }
    }
    if (nod_rng_.bernoulli(spec_.nod_probability)) {
      plan_nod(listener, start_s + length_s * nod_rng_.uniform(kBackchannelFrom, kBackchannelTo));
    }
  }
}

void GroupConversation::plan_nod(model::ObjectId listener, double at_s) {
  insert_event({Event::Kind::kNod, at_s, listener});
}

void GroupConversation::nod(Simulation& simulation, model::ObjectId listener, double at_s) {
  Human* human = simulation.mutable_human(listener);
  if (human == nullptr) {
    return;
  }
  HeadNod nod;
  nod.start_s = at_s;
  nod.cycles = 1 + static_cast<int>(nod_rng_.uniform_index(kMaxNodCycles));
  nod.cycle_s = nod_rng_.uniform(kNodCycleS[0], kNodCycleS[1]);
  nod.amplitude_rad = nod_rng_.uniform(kNodAmplitudeRad[0], kNodAmplitudeRad[1]);
  human->nod(nod);
  ++nods_;
}

void GroupConversation::plan_self_selection(model::ObjectId previous, double end_s, bool lapse) {
  const model::ObjectId next = choose_next_speaker(previous);
  const double offset_s = transition_offset_s(floor_.utterance_end_s - floor_.utterance_start_s);
  const double at_s =
      end_s + (lapse ? rng_.exponential(lapse_mean_or_first(previous)) + std::max(0.0, offset_s)
                     : offset_s);
  anticipate_turn(next, at_s);
  insert_event({Event::Kind::kStart, at_s, next});
  for (model::ObjectId member : members_) {
    if (member != next && member != previous &&
        rng_.bernoulli(spec_.simultaneous_start_probability)) {
      Event together{Event::Kind::kStart, at_s + rng_.uniform(0.0, kSimultaneousWindowS), member};
      together.drops_out = true;
      insert_event(together);
    }
  }
}

double GroupConversation::lapse_mean_or_first(model::ObjectId previous) const {
  // A group's first utterance comes soon after it forms; later silences are lapses.
  return previous == model::kNoObject ? kFirstStartMaxS / 2.0 : spec_.lapse_mean_s;
}

void GroupConversation::anticipate_turn(model::ObjectId next, double at_s) {
  const ConversationGazeShares& shares = gaze_.shares();
  for (model::ObjectId member : members_) {
    if (member != next && rng_.bernoulli(shares.anticipate_next_speaker)) {
      gaze_.anticipate(member, next, at_s - rng_.uniform(0.0, shares.anticipation_lead_max_s));
    }
  }
}

std::pair<LineKind, model::ObjectId> GroupConversation::choose_line(model::ObjectId speaker,
                                                                    const Event& event) {
  if (event.line == LineKind::kAnswer && is_participant(event.addressee)) {
    return {LineKind::kAnswer, event.addressee};
  }
  const model::ObjectId last_speaker =
      floor_.speaker != model::kNoObject ? floor_.speaker : previous_speaker_;
  if (robot_ != model::kNoObject && last_speaker == robot_) {
    return {LineKind::kAnswer, robot_};
  }
  if (robot_ != model::kNoObject && !robot_asked_since_it_spoke_ &&
      rng_.bernoulli(spec_.robot_question_probability)) {
    return {LineKind::kRobotQuestion, robot_};
  }
  std::vector<model::ObjectId> others;
  std::copy_if(members_.begin(), members_.end(), std::back_inserter(others),
               [speaker](model::ObjectId id) { return id != speaker; });
  if (others.empty()) {
    return {LineKind::kStatement, robot_};  // alone with ARI: small talk to it
  }
  model::ObjectId addressee = others[rng_.uniform_index(others.size())];
  if (others.size() > 1) {
    const double draw = rng_.uniform();
    const bool previous_listens =
        std::find(others.begin(), others.end(), previous_speaker_) != others.end();
    if (draw < kAddressGroup) {
      return {LineKind::kStatement, model::kNoObject};
    }
    if (draw < kAddressGroup + kAddressPreviousSpeaker && previous_listens) {
      addressee = previous_speaker_;
    }
  }
  return {rng_.bernoulli(spec_.question_probability) ? LineKind::kQuestion : LineKind::kStatement,
          addressee};
}

model::ObjectId GroupConversation::choose_next_speaker(model::ObjectId previous) {
  std::vector<model::ObjectId> candidates;
  std::vector<double> weights;
  for (model::ObjectId member : members_) {
    if (member != previous) {
      candidates.push_back(member);
      const double resume = member == yielded_to_robot_ && previous == robot_ ? kResumeWeight : 1.0;
      weights.push_back(talkativeness_[member] * resume);
    }
  }
  if (candidates.empty()) {
    return previous;  // the one member left with ARI goes on
  }
  if (previous == robot_) {
    yielded_to_robot_ = model::kNoObject;
  }
  return candidates[rng_.categorical(weights)];
}

double GroupConversation::transition_offset_s(double utterance_s) {
  const double early_s = spec_.transition_offset_early_s;
  const double late_s = spec_.transition_offset_late_s;
  const bool early = early_s + late_s > 0.0 && rng_.bernoulli(early_s / (early_s + late_s));
  const double offset =
      early ? spec_.transition_offset_mode_s - rng_.exponential(early_s)
            : spec_.transition_offset_mode_s + (late_s > 0.0 ? rng_.exponential(late_s) : 0.0);
  return std::max(offset, -kMaxOverlapShare * std::max(utterance_s, 0.0));
}

int GroupConversation::utterance_words() {
  const double words =
      spec_.utterance_words_median * std::exp(rng_.normal(0.0, spec_.utterance_words_log_spread));
  return std::max(1, static_cast<int>(std::lround(words)));
}

void GroupConversation::insert_event(const Event& event) {
  const auto at =
      std::upper_bound(events_.begin(), events_.end(), event.at_s,
                       [](double at_s, const Event& other) { return at_s < other.at_s; });
  events_.insert(at, event);
}

}  // namespace ari_social_sim::world
