#include "ari_social_sim/dialogue/robot_nlu.hpp"

#include <algorithm>

namespace ari_social_sim::dialogue {

RobotNlu::RobotNlu(const Nlg& nlg, const Domain& domain, const MpgtCorpus* corpus,
                   double min_similarity)
    : domain_(&domain), min_similarity_(min_similarity) {
  // Acts with a template of their own: greetings, closings, cant-help(), offer-help(), ...
  for (const DialogueAct& act : nlg.own_template_acts(true)) {
    for (const std::string& text : nlg.template_texts(true, act)) {
      add_exemplar(text, {act});
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
  index_.finish();
}

void RobotNlu::add_exemplar(const std::string& text, const std::vector<DialogueAct>& acts) {
  std::vector<DialogueAct> in_domain;
  in_domain.reserve(acts.size());
  for (const DialogueAct& act : acts) {
    in_domain.push_back(in_domain_form(act));
  }
  index_.add(text, std::move(in_domain));
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
  return index_.understand(text, min_similarity_);
}

}  // namespace ari_social_sim::dialogue
