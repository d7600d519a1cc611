#include "ari_social_sim/scenario/heard_lines.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "ari_social_sim/dialogue/robot_nlu.hpp"

namespace ari_social_sim::scenario {
namespace {

std::vector<std::string> word_set(const std::string& text) {
  std::vector<std::string> words = dialogue::normalised_words(text);
  std::sort(words.begin(), words.end());
  words.erase(std::unique(words.begin(), words.end()), words.end());
  return words;
}

double cosine(const std::vector<std::string>& a, const std::vector<std::string>& b) {
  if (a.empty() || b.empty()) {
    return 0.0;
  }
  std::vector<std::string> shared;
  std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(shared));
  return shared.size() / std::sqrt(static_cast<double>(a.size()) * b.size());
}

}  // namespace

HeardLines::HeardLines(const Script& script) {
  script.for_each_action([this](const Action& action) {
    const auto* say = std::get_if<SayAction>(&action);
    if (say != nullptr && !say->speaker.is_ari()) {
      lines_.push_back({word_set(say->text), say->text, say->act});
    }
  });
}

std::optional<std::string> HeardLines::act_of(const std::string& transcript) const {
  const std::vector<std::string> heard = word_set(transcript);
  const Line* best = nullptr;
  double best_similarity = kMinSimilarity;
  for (const Line& line : lines_) {
    const double similarity = cosine(heard, line.words);
    if (similarity >= best_similarity) {
      best = &line;
      best_similarity = similarity;
    }
  }
  return best != nullptr ? std::optional<std::string>(best->act) : std::nullopt;
}

bool HeardLines::has_act(const std::string& pattern) const {
  return std::any_of(lines_.begin(), lines_.end(),
                     [&](const Line& line) { return act_matches(pattern, line.act); });
}

std::vector<std::string> HeardLines::texts() const {
  std::vector<std::string> texts;
  for (const Line& line : lines_) {
    if (std::find(texts.begin(), texts.end(), line.text) == texts.end()) {
      texts.push_back(line.text);
    }
  }
  return texts;
}

}  // namespace ari_social_sim::scenario
