#include "ari_social_sim/world/speech_generator.hpp"

#include <cctype>
#include <cmath>
#include <cstring>
#include <sstream>

#include "ari_social_sim/core/check.hpp"
#include "ari_social_sim/core/control_characters.hpp"
#include "ari_social_sim/core/error.hpp"

namespace ari_social_sim::world {
namespace {

// Tolerance (s) for comparing sim times built from step counts with word boundaries.
constexpr double kTimeEpsilon = 1e-9;

const std::string kSilence;

}  // namespace

std::vector<std::string> spoken_words(const std::string& content) {
  std::istringstream in(content);
  std::vector<std::string> words;
  std::string word;
  while (in >> word) {
    words.push_back(word);
  }
  return words;
}

SpeechGenerator::SpeechGenerator(double words_per_minute) : words_per_minute_(words_per_minute) {
  ARI_CHECK(words_per_minute > 0.0);
}

double SpeechGenerator::duration_s(const std::string& content) const {
  return static_cast<double>(spoken_words(content).size()) * 60.0 / words_per_minute_;
}

namespace {

// Throws core::RequestError unless `act` is one act or several in the notations the suite uses:
// a name with optional bracketed arguments (QUESTION:TIME, greet(), request(location(toilet)),
// inform(time=now)), several separated by `;` or `,` and at most one space (the dialogue writes
// `greet(); request(...)`). Consumers match acts against patterns and split them at the
// separators: a stray space, quote or bracket would make an act that no pattern can name.
void check_act_grammar(const std::string& act) {
  const auto refuse = [&act](const std::string& what, size_t at) {
    throw core::RequestError(
        "say: act: expected acts such as QUESTION:TIME or greet(); request(location(toilet)): "
        "letters, digits and _:=,.*'- with balanced brackets, separated by '; ', got '" +
        act + "' (" + what + " at offset " + std::to_string(at) + ")");
  };
  int depth = 0;
  bool act_start = true;  // the next character begins an act: a letter
  for (size_t i = 0; i < act.size(); ++i) {
    const char c = act[i];
    if (act_start && !std::isalpha(static_cast<unsigned char>(c))) {
      refuse("an act that does not start with a letter", i);
    }
    act_start = false;
    if (depth == 0 && (c == ';' || c == ',')) {
      i += i + 1 < act.size() && act[i + 1] == ' ' ? 1 : 0;
      act_start = true;
    } else if (c == '(') {
      ++depth;
    } else if (c == ')' && --depth < 0) {
      refuse("a ')' without its '('", i);
    } else if (!std::isalnum(static_cast<unsigned char>(c)) && !std::strchr("_:=,.*'-()", c)) {
      refuse(std::string("the character '") + c + "'", i);
    }
  }
  if (depth != 0) {
    refuse("an unclosed '('", act.size());
  }
  if (act_start) {
    refuse("no act after the last separator", act.size());
  }
}

}  // namespace

void SpeechGenerator::say(const std::string& act, const std::string& content, double now_s) {
  // Words are split at spaces, tabs and newlines; nothing else below 0x20 is text. An act is one
  // token (QUESTION:TIME, greet(), inform(time=now)): no whitespace at all.
  core::check_no_control_characters("say: content", content, "\t\n");
  core::check_no_control_characters("say: act", act, "");
  if (content.size() > kMaxContentBytes) {
    throw core::RequestError("say: content: expected at most " + std::to_string(kMaxContentBytes) +
                             " bytes, got " + std::to_string(content.size()));
  }
  if (act.size() > kMaxActBytes) {
    throw core::RequestError("say: act: expected at most " + std::to_string(kMaxActBytes) +
                             " bytes, got " + std::to_string(act.size()));
  }
  std::vector<std::string> words = spoken_words(content);
  if (words.empty()) {
    throw core::RequestError("say: content has no words");
  }
  if (act.empty()) {
    throw core::RequestError("say: act is empty (e.g. QUESTION:TIME)");
  }
  check_act_grammar(act);
  if (is_speaking()) {
    finish(now_s, true);
  }
  act_ = act;
  content_ = content;
  words_ = std::move(words);
  word_index_ = 0;
  start_s_ = now_s;
}

const std::string& SpeechGenerator::current_word() const {
  return words_.empty() ? kSilence : words_[word_index_];
}

void SpeechGenerator::step(Object& owner, const StepContext& context) {
  if (!is_speaking()) {
    return;
  }
  const double seconds_per_word = 60.0 / words_per_minute_;
  // The step runs at time_s and the world afterwards stands at time_s + dt_s.
  const double now_s = context.time_s + context.dt_s;
  const double end_s = start_s_ + static_cast<double>(words_.size()) * seconds_per_word;
  if (now_s + kTimeEpsilon >= end_s) {
    finish(now_s, false);
    return;
  }
  word_index_ =
      static_cast<size_t>(std::floor((now_s - start_s_) / seconds_per_word + kTimeEpsilon));
}

void SpeechGenerator::stop(double now_s) {
  if (is_speaking()) {
    finish(now_s, true);
  }
}

double SpeechGenerator::end_s() const {
  return start_s_ + static_cast<double>(words_.size()) * 60.0 / words_per_minute_;
}

void SpeechGenerator::finish(double end_s, bool interrupted) {
  history_.push_back({act_, content_, start_s_, end_s, interrupted});
  if (history_.size() > kHistoryLength) {
    history_.pop_front();
  }
  act_.clear();
  content_.clear();
  words_.clear();
  word_index_ = 0;
  start_s_ = 0.0;
}

}  // namespace ari_social_sim::world
