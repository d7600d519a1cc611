#include "ari_social_sim/dialogue/robot_nlu.hpp"

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

RobotNlu::RobotNlu(const Nlg& nlg, const Domain& domain, const MpgtCorpus* corpus,
                   double min_similarity)
    : domain_(&domain), min_similarity_(min_similarity) {
  // Acts with a template of their own: greetings, closings, cant-help(), offer-help(), ...
  for (const auto& entry : nlg.templates().robot) {
    if (entry.first.find('*') == std::string::npos && entry.first != "none") {
      const DialogueAct act = parse_act(entry.first, "robot template");
      for (const std::string& text : nlg.template_texts(true, act)) {
        add_exemplar(text, {act});
      }
    }
  }
  // The answer to every goal of the domain, and its repetition.
  for (const PredicateSpec& predicate : domain.predicates()) {
    for (const DomainObject& object : predicate.objects) {
      const DialogueAct answer = domain.answer_act(Goal{{}, predicate.name, object.path});
      for (const std::string& text : nlg.template_texts(true, answer)) {
        add_exemplar(text, {answer});
      }
      if (!answer.path().empty()) {
        const DialogueAct repeat = DialogueAct::from_path("p-repet", answer.path());
        for (const std::string& text : nlg.template_texts(true, repeat)) {
          add_exemplar(text, {repeat});
        }
      }
    }
  }
  // What MPGT's ARI said: the whole utterance, and sentence by sentence when sentences and acts
  // pair up one to one.
  if (corpus != nullptr) {
    for (const CorpusDialogue& dialogue : corpus->dialogues) {
      for (const CorpusUtterance& u : dialogue.utterances) {
        if (!u.is_robot() || u.acts.empty()) {
          continue;
        }
        add_exemplar(u.text, u.acts);
        const std::vector<std::string> sentences = split_sentences(u.text);
        if (sentences.size() == u.acts.size() && sentences.size() > 1) {
          for (size_t i = 0; i < sentences.size(); ++i) {
            add_exemplar(sentences[i], {u.acts[i]});
          }
        }
      }
    }
  }
  weigh_exemplars();
}

void RobotNlu::add_exemplar(const std::string& text, const std::vector<DialogueAct>& acts) {
  std::vector<std::string> words = normalised_words(text);
  if (words.empty()) {
    return;
  }
  for (const std::string& word : words) {
    word_ids_.emplace(word, static_cast<int>(word_ids_.size()));
  }
  exemplar_words_.push_back(std::move(words));
  Exemplar exemplar;
  for (const DialogueAct& act : acts) {
    exemplar.acts.push_back(in_domain_form(act));
  }
  exemplars_.push_back(std::move(exemplar));
}

void RobotNlu::weigh_exemplars() {
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

std::map<int, double> RobotNlu::weigh(const std::vector<std::string>& words) const {
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

RobotNlu::Match RobotNlu::best_match(const std::string& sentence) const {
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

DialogueAct RobotNlu::in_domain_form(const DialogueAct& act) const {
  if (act.intent != "inform" || act.path().empty() || domain_->goal_of_answer(act)) {
    return act;
  }
  // An inform whose path ends with a domain object's path answers that object's goal, in the
  // domain's words: inform(location(cafe)) -> inform(directions(cafe)). The longest object wins.
  const std::vector<std::string> path = act.path();
  const PredicateSpec* best_predicate = nullptr;
  const DomainObject* best_object = nullptr;
  for (const PredicateSpec& predicate : domain_->predicates()) {
    for (const DomainObject& object : predicate.objects) {
      const size_t n = object.path.size();
      if (n == 0 || n > path.size() ||
          !std::equal(object.path.begin(), object.path.end(), path.end() - static_cast<long>(n))) {
        continue;
      }
      if (best_object == nullptr || n > best_object->path.size()) {
        best_predicate = &predicate;
        best_object = &object;
      }
    }
  }
  if (best_object == nullptr) {
    return act;
  }
  return domain_->answer_act(Goal{{}, best_predicate->name, best_object->path});
}

std::vector<DialogueAct> RobotNlu::understand(const std::string& text) const {
  std::vector<DialogueAct> acts;
  for (const std::string& sentence : split_sentences(text)) {
    const Match match = best_match(sentence);
    if (match.exemplar == nullptr || match.similarity < min_similarity_) {
      continue;
    }
    for (const DialogueAct& act : match.exemplar->acts) {
      add_unique(acts, act);
    }
  }
  return acts;
}

}  // namespace ari_social_sim::dialogue
