#pragma once

#include <string>
#include <vector>

#include "ari_social_sim/core/rng.hpp"

namespace ari_social_sim::dialogue {

/// One text of the NLG templates (config/dialogue/nlg_templates.yaml) in the small grammar that
/// gives each template many surface forms: `[a|b|c]` says one of a, b or c, drawn uniformly; an
/// alternative may be empty (`[Excuse me, |]`), so a group with an empty alternative is optional.
/// Groups do not nest. `{object}` is the only placeholder, filled in by the NLG.
class TemplateText {
 public:
  /// Parses `text`; `field` names it in messages (`file: templates[3].texts[1]`). Throws
  /// core::ConfigError on an unbalanced `[` or `]`, a nested `[`, a `|` outside brackets, a group
  /// with fewer than two alternatives or a placeholder other than {object}.
  static TemplateText parse(const std::string& text, const std::string& field);

  /// One surface form, each group's alternative drawn from `rng` (same draws, same text).
  std::string draw(core::Rng& rng) const;

  /// Every surface form, in order, when there are at most `cap`. Above that, a cover: text i
  /// takes alternative i mod n of each group of n, so that every alternative (every word) appears
  /// in one of max(n) texts.
  std::vector<std::string> expand(size_t cap) const;

  /// The number of surface forms (the product of the group sizes), saturating at SIZE_MAX.
  size_t form_count() const;

 private:
  // Literal runs are parts of one alternative; groups have two or more.
  std::vector<std::vector<std::string>> parts_;
};

/// `text` as a sentence: runs of spaces made one, none before `,.?!:` nor at either end, and the
/// first letter of the text and of each sentence after `.?!` in upper case. Empty alternatives
/// leave such gaps ("[Excuse me, |]where is it?" -> "Where is it?").
std::string tidy_sentence_text(const std::string& text);

}  // namespace ari_social_sim::dialogue
