#pragma once

#include <deque>
#include <string>
#include <vector>

#include "ari_social_sim/world/object.hpp"

namespace ari_social_sim::world {

/// One finished (or interrupted) speech act in a speaker's history.
struct SpeechRecord {
  std::string act;
  std::string content;
  double start_s{0.0};
  double end_s{0.0};
  bool interrupted{false};
};

/// The words of an utterance as the world says them, one at a time: runs of non-whitespace.
std::vector<std::string> spoken_words(const std::string& content);

/// D6.4 §3.3.3: plays an utterance word by word at a words-per-minute rate and keeps the history of
/// acts with their start and end times: the last kHistoryLength of them, so that a speaker who
/// talks for hours does not grow without bound (only the previous act is published). Word i is
/// current during [start + i * 60 / wpm, start + (i + 1) * 60 / wpm); the act ends at the first
/// step at or after start + n * 60 / wpm, so an n-word act lasts n * 60 / wpm plus at most one
/// step.
class SpeechGenerator : public Component {
 public:
  static constexpr size_t kHistoryLength = 32;
  /// Longest content and act a speaker takes (bytes): 4096 bytes is several minutes of speech, as
  /// the dialogue environment's text limit; an act is an intent and a few slots.
  static constexpr size_t kMaxContentBytes = 4096;
  static constexpr size_t kMaxActBytes = 256;

  explicit SpeechGenerator(double words_per_minute);

  ComponentPhase phase() const override { return ComponentPhase::kGenerator; }
  void step(Object& owner, const StepContext& context) override;

  /// Starts an act now; an act in progress is cut off and recorded as interrupted. Throws
  /// core::RequestError if the content has no words or more than kMaxContentBytes, or the act is
  /// empty or longer than kMaxActBytes.
  void say(const std::string& act, const std::string& content, double now_s);
  /// Seconds an utterance of this content takes at this speaker's rate.
  double duration_s(const std::string& content) const;
  /// Stops the act in progress now, recorded as interrupted (a speaker who gives way); nothing
  /// when silent.
  void stop(double now_s);

  bool is_speaking() const { return !words_.empty(); }
  const std::string& act() const { return act_; }
  const std::string& content() const { return content_; }
  /// The word being played; empty when silent.
  const std::string& current_word() const;
  size_t word_index() const { return word_index_; }
  double start_s() const { return start_s_; }
  /// When the act in progress ends if nobody cuts it off (s); start_s() when silent.
  double end_s() const;
  /// The most recent act that finished (D6.4's previous_speech_act); empty before the first.
  const SpeechRecord* previous() const { return history_.empty() ? nullptr : &history_.back(); }
  /// The last kHistoryLength finished acts, oldest first.
  const std::deque<SpeechRecord>& history() const { return history_; }
  double words_per_minute() const { return words_per_minute_; }

 private:
  void finish(double end_s, bool interrupted);

  double words_per_minute_;
  std::string act_;
  std::string content_;
  std::vector<std::string> words_;
  size_t word_index_{0};
  double start_s_{0.0};
  std::deque<SpeechRecord> history_;
};

}  // namespace ari_social_sim::world
