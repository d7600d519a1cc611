#include "ari_social_sim/dialogue/exemplar_index.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <set>

namespace ari_social_sim::dialogue {
namespace {

bool is_sentence_end(char c) {
  return c == '.' || c == '?' || c == '!';
}

void add_unique(std::vector<DialogueAct>& acts, const DialogueAct& act) {
  if (std::find(acts.begin(), acts.end(), act) == acts.end()) {
    acts.push_back(act);
  }
}

}  // namespace

std::vector<std::string> normalised_words(const std::string& text) {
  std::vector<std::string> words;
  std::string word;
  for (char c : text + " ") {
    const auto u = static_cast<unsigned char>(c);
    if (std::isalnum(u) || c == '\'') {
      word += static_cast<char>(std::tolower(u));
    } else if (!word.empty()) {
      words.push_back(std::move(word));
      word.clear();
    }
  }
  return words;
}

std::vector<std::string> split_sentences(const std::string& text) {
  std::vector<std::string> sentences;
  std::string sentence;
  for (char c : text + ".") {
    if (!is_sentence_end(c)) {
      sentence += c;
    } else if (!normalised_words(sentence).empty()) {
      sentences.push_back(std::move(sentence));
      sentence.clear();
    } else {
      sentence.clear();
    }
  }
  return sentences;
}

void ExemplarIndex::add(const std::string& text, std::vector<DialogueAct> acts) {
  std::vector<std::string> words = normalised_words(text);
  if (words.empty()) {
    return;
  }
  for (const std::string& word : words) {
    word_ids_.emplace(word, static_cast<int>(word_ids_.size()));
  }
  exemplar_words_.push_back(std::move(words));
  exemplars_.push_back(Exemplar{{}, std::move(acts)});
}

void ExemplarIndex::finish() {
  // Smoothed inverse document frequency: log(1 + N / df), so that words every exemplar shares
  // ("the") count little and object names ("toilets") decide.
  std::vector<int> document_frequency(word_ids_.size(), 0);
  for (const auto& words : exemplar_words_) {
    for (const std::string& word : std::set<std::string>(words.begin(), words.end())) {
      ++document_frequency[word_ids_.at(word)];
    }
  }
  const double n = static_cast<double>(exemplar_words_.size());
  idf_.resize(word_ids_.size());
  for (size_t id = 0; id < idf_.size(); ++id) {
    idf_[id] = std::log(1.0 + n / document_frequency[id]);
  }
  for (size_t i = 0; i < exemplars_.size(); ++i) {
    exemplars_[i].weights = weigh(exemplar_words_[i]);
  }
  exemplar_words_.clear();
}

std::map<int, double> ExemplarIndex::weigh(const std::vector<std::string>& words) const {
  // Binary term weights: a word said twice is no more the topic than said once.
  std::map<int, double> weights;
  for (const std::string& word : words) {
    const auto id = word_ids_.find(word);
    if (id != word_ids_.end()) {
      weights[id->second] = idf_[id->second];
    }
  }
  double norm = 0.0;
  for (const auto& entry : weights) {
    norm += entry.second * entry.second;
  }
  norm = std::sqrt(norm);
  for (auto& entry : weights) {
    entry.second /= norm;
  }
  return weights;
}

ExemplarIndex::Match ExemplarIndex::best_match(const std::string& sentence) const {
  const std::map<int, double> query = weigh(normalised_words(sentence));
  Match best;
  for (const Exemplar& exemplar : exemplars_) {
    double dot = 0.0;
    for (const auto& [id, weight] : query) {
      const auto found = exemplar.weights.find(id);
      if (found != exemplar.weights.end()) {
        dot += weight * found->second;
      }
    }
    // Strictly greater: on a tie the earlier exemplar (templates before corpus) wins.
    if (dot > best.similarity) {
      best = {dot, &exemplar};
    }
  }
  return best;
}

std::vector<DialogueAct> ExemplarIndex::understand(const std::string& text,
                                                   double min_similarity) const {
  std::vector<DialogueAct> acts;
  for (const std::string& sentence : split_sentences(text)) {
    const Match match = best_match(sentence);
    if (match.exemplar == nullptr || match.similarity < min_similarity) {
      continue;
    }
    for (const DialogueAct& act : match.exemplar->acts) {
      add_unique(acts, act);
    }
  }
  return acts;
}

}  // namespace ari_social_sim::dialogue
