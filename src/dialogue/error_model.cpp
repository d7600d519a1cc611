#include "ari_social_sim/dialogue/error_model.hpp"

#include <algorithm>

#include "ari_social_sim/core/config_check.hpp"
#include "ari_social_sim/dialogue/text.hpp"

namespace ari_social_sim::dialogue {
namespace {

const std::string& pick(const std::vector<std::string>& names, core::Rng& rng) {
  return names[rng.uniform_index(names.size())];
}

}  // namespace

void ErrorModelConfig::validate() const {
  core::check_fields(*this, "ErrorModelConfig");
}

ErrorModel::ErrorModel(ErrorModelConfig config, const Domain& domain,
                       std::vector<std::string> vocabulary)
    : config_(config),
      slots_(domain.slot_names()),
      values_(domain.object_names()),
      vocabulary_(std::move(vocabulary)) {
  config_.validate();
  if (vocabulary_.empty()) {
    vocabulary_ = values_;
  }
  if (vocabulary_.empty()) {
    vocabulary_ = {"um"};
  }
}

Perception ErrorModel::apply(const Utterance& utterance, const std::vector<std::string>& humans,
                             core::Rng& rng) const {
  Perception heard;
  // Stages in a fixed order so that a seed gives the same draws: drop, speaker, addressee,
  // words, semantics.
  if (rng.bernoulli(config_.drop_rate)) {
    heard.dropped = true;
    heard.confidence = 0.0;
    return heard;
  }
  heard.speaker = utterance.speaker;
  if (humans.size() > 1 && rng.bernoulli(config_.misattribution_rate)) {
    std::vector<std::string> others;
    for (const std::string& human : humans) {
      if (human != utterance.speaker) {
        others.push_back(human);
      }
    }
    heard.speaker = pick(others, rng);
  }
  heard.addressees = utterance.addressees;
  if (rng.bernoulli(config_.wrong_addressee_rate)) {
    const bool to_robot = std::find(heard.addressees.begin(), heard.addressees.end(), kRobot) !=
                          heard.addressees.end();
    heard.addressees.clear();
    if (to_robot) {
      for (const std::string& human : humans) {
        if (human != utterance.speaker) {
          heard.addressees.push_back(human);
        }
      }
    }
    if (heard.addressees.empty()) {
      heard.addressees.emplace_back(kRobot);
    }
  }
  heard.text = utterance.text;
  heard.word_errors = corrupt_words(heard.text, rng);
  const double words = std::max<double>(1.0, split_words(utterance.text).size());
  heard.confidence = std::clamp(
      1.0 - heard.word_errors / words + rng.normal(0.0, config_.confidence_noise), 0.0, 1.0);
  heard.acts = utterance.acts;
  if (!heard.acts.empty() && rng.bernoulli(config_.semantic_error_rate)) {
    confuse(heard.acts, rng);
  }
  return heard;
}

int ErrorModel::corrupt_words(std::string& text, core::Rng& rng) const {
  // Each word is hit with P = WER; a hit substitutes (1/2), deletes (1/4) or inserts after it
  // (1/4), one error each, so the expected WER is the target.
  const std::vector<std::string> words = split_words(text);
  std::string out;
  int errors = 0;
  auto emit = [&out](const std::string& word) { out += (out.empty() ? "" : " ") + word; };
  for (const std::string& word : words) {
    if (!rng.bernoulli(config_.word_error_rate)) {
      emit(word);
      continue;
    }
    ++errors;
    const double kind = rng.uniform();
    if (kind < 0.5) {
      emit(pick(vocabulary_, rng));
    } else if (kind < 0.75) {
      continue;
    } else {
      emit(word);
      emit(pick(vocabulary_, rng));
    }
  }
  text = std::move(out);
  return errors;
}

void ErrorModel::confuse(std::vector<DialogueAct>& acts, core::Rng& rng) const {
  DialogueAct& act = acts[rng.uniform_index(acts.size())];
  const double kind = rng.uniform();
  std::vector<std::string> path = act.path();
  if (kind < config_.intent_share || path.empty()) {
    act.intent = pick(mpgt_intents(), rng);
    return;
  }
  if (kind < config_.intent_share + config_.slot_share && !slots_.empty()) {
    path[rng.uniform_index(path.size() > 1 ? path.size() - 1 : 1)] = pick(slots_, rng);
  } else if (!values_.empty()) {
    path.back() = pick(values_, rng);
  }
  act = DialogueAct::from_path(act.intent, std::move(path));
}

}  // namespace ari_social_sim::dialogue
