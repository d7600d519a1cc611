#pragma once

#include <map>
#include <string>
#include <vector>

#include "ari_social_sim/core/config_fields.hpp"
#include "ari_social_sim/core/rng.hpp"
#include "ari_social_sim/core/yaml_map.hpp"
#include "ari_social_sim/dialogue/dialogue_act.hpp"
#include "ari_social_sim/dialogue/mpgt_corpus.hpp"
#include "ari_social_sim/dialogue/template_text.hpp"

namespace ari_social_sim::dialogue {

/// How acts become text: templates per act (config/dialogue/nlg_templates.yaml), or retrieval of
/// a real MPGT utterance with the same acts, falling back to templates when the corpus has none.
enum class NlgMode { kTemplate, kRetrieval };

inline constexpr core::Choice<NlgMode> kNlgModes[] = {{NlgMode::kTemplate, "template"},
                                                      {NlgMode::kRetrieval, "retrieval"}};

/// `template` or `retrieval`; throws core::ConfigError naming `field` otherwise.
NlgMode parse_nlg_mode(const std::string& text, const std::string& field);

/// Templates keyed by act pattern and speaker side, with surface words for slot names.
struct NlgTemplates {
  std::map<std::string, std::vector<TemplateText>> human;  ///< key -> texts
  std::map<std::string, std::vector<TemplateText>> robot;
  std::map<std::string, std::string> words;  ///< name -> surface text (cafe -> cafeteria)

  /// Reads a template file. Keys are acts (`thank()`), patterns with `*` for the innermost name
  /// (`request(location(*))`) or `none`; texts are TemplateText (alternatives in [a|b], {object}).
  /// Throws core::ConfigError naming the file and entry on an unknown intent, a bad speaker, an
  /// empty text list or a text that is not TemplateText.
  static NlgTemplates load(const std::string& file_path);
  static NlgTemplates parse(const core::YamlMap& map);
};

/// Forms of one template text that template_texts() and vocabulary() list at most: enough for
/// every text of the shipped templates, so that RobotNlu knows each form ARI can say.
inline constexpr size_t kMaxFormsPerText = 512;

/// Realises acts as text. Stateless apart from its constant tables; draws from the caller's Rng.
class Nlg {
 public:
  /// `corpus` may be null in template mode; it is indexed once here.
  Nlg(NlgTemplates templates, const MpgtCorpus* corpus, NlgMode mode);

  /// Text for `acts` (empty acts: an unannotated utterance) said by ARI or by a human.
  std::string realise(bool robot, const std::vector<DialogueAct>& acts, core::Rng& rng) const;

  /// Every surface form of the template texts for `act` said by ARI or a human, {object} filled
  /// in, from the most specific matching key (what realise() draws from; a text with more than
  /// kMaxFormsPerText forms gives a cover of its alternatives, TemplateText::expand); empty when
  /// no key matches.
  std::vector<std::string> template_texts(bool robot, const DialogueAct& act) const;
  /// The acts with a template of their own on ARI's or the humans' side (keys without `*`, not
  /// `none`): greet(), thank(), offer-help(), ... in key order.
  std::vector<DialogueAct> own_template_acts(bool robot) const;
  const NlgTemplates& templates() const { return templates_; }

  NlgMode mode() const { return mode_; }
  /// Every word of the template texts' forms and of the retrieval index, for ASR substitutions.
  std::vector<std::string> vocabulary() const;

 private:
  struct TemplateMatch {
    const std::vector<TemplateText>* texts{nullptr};  ///< null when no key matches
    std::vector<std::string> names;                   ///< what {object} stands for
  };
  TemplateMatch find_template(bool robot, const DialogueAct& act) const;
  std::string from_template(bool robot, const DialogueAct* act, core::Rng& rng) const;
  std::string surface(const std::vector<std::string>& names) const;
  std::string filled(const std::string& form, const std::vector<std::string>& names) const;

  NlgTemplates templates_;
  NlgMode mode_;
  // Retrieval index: acts string (`none` for unannotated) -> real utterances.
  std::map<std::string, std::vector<std::string>> corpus_human_;
  std::map<std::string, std::vector<std::string>> corpus_robot_;
};

}  // namespace ari_social_sim::dialogue
