#include "ari_social_sim/world/conversation_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

#include "ari_social_sim/world/speech_generator.hpp"

namespace ari_social_sim::world {
namespace {

// Backchannels are no turns (GroupConversation's act for them).
constexpr const char* kBackchannelAct = "backchannel()";
// ARI talks over a member who has more than this (s) of an utterance left (GroupConversation's
// rule).
constexpr double kInterruptionMarginS = 0.5;
// Width (s) of the bins the mode of the transition offsets is taken over.
constexpr double kModeBinS = 0.1;

bool holds_floor(const SpeechSnapshot& speech) {
  return speech.is_speaking && speech.act != kBackchannelAct;
}

double planned_end_s(const SpeechSnapshot& speech) {
  return speech.start_s +
         static_cast<double>(spoken_words(speech.content).size()) * 60.0 / speech.words_per_minute;
}

bool takes_part(const GroupSnapshot& group, model::ObjectId id) {
  return id != model::kNoObject &&
         (id == group.robot_joining ||
          std::find(group.members.begin(), group.members.end(), id) != group.members.end());
}

double median(std::vector<double> values) {
  if (values.empty()) {
    return 0.0;
  }
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

double mode(const std::vector<double>& values) {
  std::map<long, int> bins;
  for (double value : values) {
    ++bins[static_cast<long>(std::floor(value / kModeBinS))];
  }
  const auto fullest = std::max_element(
      bins.begin(), bins.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
  return fullest == bins.end() ? 0.0 : (static_cast<double>(fullest->first) + 0.5) * kModeBinS;
}

double share(double part, double whole) {
  return whole > 0.0 ? part / whole : 0.0;
}

}  // namespace

void ConversationMetrics::observe(const WorldSnapshot& snapshot) {
  const double now_s = snapshot.time_s;
  if (last_time_s_ >= 0.0 && now_s <= last_time_s_) {
    close_all();
    ++run_;
    last_time_s_ = -1.0;
  }
  const double dt_s = last_time_s_ < 0.0 ? 0.0 : now_s - last_time_s_;
  last_time_s_ = now_s;
  for (const GroupSnapshot& group : snapshot.groups) {
    if (!group.converses) {
      continue;
    }
    conversation_s_ += dt_s;
    for (const HumanSnapshot& human : snapshot.humans) {
      if (human.group_id == group.id) {
        track_speech(human.id, group.id, human.speech, now_s);
        speaking_s_[human.id] += holds_floor(human.speech) ? dt_s : 0.0;
      }
    }
    if (snapshot.ari && group.robot_joining == snapshot.ari->id) {
      track_speech(snapshot.ari->id, group.id, snapshot.ari->speech, now_s);
      speaking_s_[snapshot.ari->id] += holds_floor(snapshot.ari->speech) ? dt_s : 0.0;
    }
    count_gaze(snapshot, group, dt_s);
    follow_robot(snapshot, group);
  }
}

void ConversationMetrics::follow_robot(const WorldSnapshot& snapshot, const GroupSnapshot& group) {
  // The floor of the state before: the conversation may already have silenced a member who
  // yields to ARI in the step that hears ARI begin.
  const Floor before = last_floor_[group.id];
  last_floor_[group.id] = {group.speaker, group.utterance_end_s};
  if (!snapshot.ari || group.robot_joining != snapshot.ari->id) {
    return;
  }
  const model::ObjectId ari = snapshot.ari->id;
  if (robot_joined_s_ < 0.0) {
    robot_joined_s_ = snapshot.time_s;
    robot_entered_in_pause_ = group.speaker == model::kNoObject || group.speaker == ari ? 1 : 0;
  }
  if (robot_addressed_after_s_ < 0.0 && group.addressee == ari && group.speaker != ari &&
      group.speaker != model::kNoObject) {
    robot_addressed_after_s_ = snapshot.time_s - robot_joined_s_;
  }
  const SpeechSnapshot& speech = snapshot.ari->speech;
  if (!speech.is_speaking || speech.start_s == robot_last_start_s_) {
    return;
  }
  robot_last_start_s_ = speech.start_s;
  if (before.speaker != model::kNoObject && before.speaker != ari &&
      before.utterance_end_s > speech.start_s + kInterruptionMarginS) {
    ++robot_interruptions_;
  }
}

void ConversationMetrics::close_all() {
  for (const auto& [speaker, open] : open_) {
    utterances_.push_back(
        {run_, open.group, speaker, open.start_s, std::min(last_time_s_, open.planned_end_s)});
  }
  open_.clear();
}

void ConversationMetrics::track_speech(model::ObjectId speaker, model::ObjectId group,
                                       const SpeechSnapshot& speech, double now_s) {
  const auto open = open_.find(speaker);
  const bool same =
      open != open_.end() && holds_floor(speech) && open->second.start_s == speech.start_s;
  if (open != open_.end() && !same) {
    utterances_.push_back({run_, open->second.group, speaker, open->second.start_s,
                           std::min(now_s, open->second.planned_end_s)});
    open_.erase(open);
  }
  if (holds_floor(speech) && !same) {
    open_[speaker] = {speech.start_s, planned_end_s(speech), group};
  }
}

void ConversationMetrics::count_gaze(const WorldSnapshot& snapshot, const GroupSnapshot& group,
                                     double dt_s) {
  model::ObjectId speaker = model::kNoObject;
  int speakers = 0;
  for (const HumanSnapshot& human : snapshot.humans) {
    if (human.group_id == group.id && holds_floor(human.speech)) {
      speaker = human.id;
      ++speakers;
    }
  }
  if (snapshot.ari && group.robot_joining == snapshot.ari->id &&
      holds_floor(snapshot.ari->speech)) {
    speaker = snapshot.ari->id;
    ++speakers;
  }
  if (speakers != 1) {
    return;  // silence or overlap: no one person to look at
  }
  for (const HumanSnapshot& human : snapshot.humans) {
    if (human.group_id != group.id) {
      continue;
    }
    const bool is_speaker = human.id == speaker;
    const model::ObjectId wanted = is_speaker ? group.addressee : speaker;
    if (is_speaker && (!takes_part(group, wanted) || wanted == speaker)) {
      continue;  // speaking to the whole group: no one addressee to look at
    }
    GazeCount& count = is_speaker ? speakers_ : listeners_;
    count.total_s += dt_s;
    count.at_people_s += takes_part(group, human.gaze.target) ? dt_s : 0.0;
    count.at_target_s += human.gaze.target == wanted ? dt_s : 0.0;
  }
}

ConversationSummary ConversationMetrics::summary() const {
  std::vector<Utterance> utterances = utterances_;
  for (const auto& [speaker, open] : open_) {
    utterances.push_back(
        {run_, open.group, speaker, open.start_s, std::min(last_time_s_, open.planned_end_s)});
  }
  std::stable_sort(utterances.begin(), utterances.end(),
                   [](const Utterance& a, const Utterance& b) {
                     return std::tie(a.run, a.start_s) < std::tie(b.run, b.start_s);
                   });
  ConversationSummary summary;
  // Each utterance follows the one of its group that reaches furthest: a false start inside
  // another's turn does not become the turn the next speaker follows.
  std::map<std::pair<size_t, model::ObjectId>, const Utterance*> floor_of_group;
  size_t turns = 0;
  for (const Utterance& utterance : utterances) {
    const Utterance*& floor = floor_of_group[{utterance.run, utterance.group}];
    if (floor == nullptr || floor->speaker != utterance.speaker) {
      ++turns;
      if (floor != nullptr) {
        summary.transition_offsets_s.push_back(utterance.start_s - floor->end_s);
      }
    }
    if (floor == nullptr || utterance.end_s >= floor->end_s) {
      floor = &utterance;
    }
  }
  const std::vector<double>& offsets = summary.transition_offsets_s;
  summary.overlap_share =
      share(static_cast<double>(std::count_if(offsets.begin(), offsets.end(),
                                              [](double offset) { return offset < 0.0; })),
            static_cast<double>(offsets.size()));
  summary.offset_median_s = median(offsets);
  summary.offset_mode_s = mode(offsets);
  summary.turns_per_minute = share(static_cast<double>(turns), conversation_s_ / 60.0);
  summary.listener_gaze_at_speaker = share(listeners_.at_target_s, listeners_.total_s);
  summary.listener_people_gaze_at_speaker = share(listeners_.at_target_s, listeners_.at_people_s);
  summary.speaker_gaze_at_addressee = share(speakers_.at_target_s, speakers_.total_s);
  summary.speaker_people_gaze_at_addressee = share(speakers_.at_target_s, speakers_.at_people_s);
  double speaking_total = 0.0;
  for (const auto& [id, seconds] : speaking_s_) {
    speaking_total += seconds;
  }
  for (const auto& [id, seconds] : speaking_s_) {
    summary.floor_share[id] = share(seconds, speaking_total);
  }
  summary.robot_interruptions = robot_interruptions_;
  summary.robot_addressed_after_s = robot_addressed_after_s_;
  summary.robot_entered_in_pause = robot_entered_in_pause_;
  return summary;
}

ConversationFigures ConversationFigures::of(const ConversationSummary& summary,
                                            model::ObjectId ari) {
  ConversationFigures figures;
  figures.turn_transitions = static_cast<int>(summary.transition_offsets_s.size());
  figures.overlap_share = summary.overlap_share;
  figures.listener_gaze_at_speaker = summary.listener_people_gaze_at_speaker;
  const auto ari_share = summary.floor_share.find(ari);
  figures.ari_floor_share = ari_share != summary.floor_share.end() ? ari_share->second : 0.0;
  figures.ari_interruptions = summary.robot_interruptions;
  figures.ari_addressed_after_s = summary.robot_addressed_after_s;
  figures.ari_entered_in_pause = summary.robot_entered_in_pause;
  return figures;
}

}  // namespace ari_social_sim::world
