#include "ari_social_sim/dialogue/human_nlu.hpp"

namespace ari_social_sim::dialogue {
namespace {

void add_template_texts(const Nlg& nlg, const DialogueAct& act, ExemplarIndex& index) {
  for (const std::string& text : nlg.template_texts(false, act)) {
    index.add(text, {act});
  }
}

}  // namespace

HumanNlu::HumanNlu(const Nlg& nlg, const Domain& domain, const MpgtCorpus* corpus,
                   double min_similarity)
    : min_similarity_(min_similarity) {
  // Acts with a template of their own: greet(), thank(), r-repet(), bye(), ...
  for (const DialogueAct& act : nlg.own_template_acts(false)) {
    add_template_texts(nlg, act, index_);
  }
  // Every way of asking for every goal of the domain.
  for (const PredicateSpec& predicate : domain.predicates()) {
    for (const DomainObject& object : predicate.objects) {
      for (const DialogueAct& ask : domain.ask_acts(Goal{{}, predicate.name, object.path})) {
        add_template_texts(nlg, ask, index_);
      }
    }
  }
  if (corpus != nullptr) {
    for (const CorpusDialogue& dialogue : corpus->dialogues) {
      for (const CorpusUtterance& u : dialogue.utterances) {
        if (!u.is_robot() && !u.acts.empty()) {
          index_.add(u.text, u.acts);
        }
      }
    }
  }
  index_.finish();
}

}  // namespace ari_social_sim::dialogue
