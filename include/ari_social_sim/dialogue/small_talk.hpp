#pragma once

#include <string>
#include <vector>

#include "ari_social_sim/core/rng.hpp"
#include "ari_social_sim/core/yaml_map.hpp"
#include "ari_social_sim/dialogue/template_text.hpp"

namespace ari_social_sim::dialogue {

/// The small talk of people who wait together (config/dialogue/small_talk.yaml): texts per kind
/// of line in TemplateText's grammar, {object} standing for a topic drawn from `topics`.
struct SmallTalk {
  std::vector<std::string> topics;
  std::vector<TemplateText> statements;
  std::vector<TemplateText> questions;
  std::vector<TemplateText> answers;
  std::vector<TemplateText> backchannels;

  /// Reads a small-talk file. Throws core::ConfigError naming the file and field on a missing or
  /// empty list, a text that is not TemplateText, or {object} in a file without topics.
  static SmallTalk load(const std::string& file_path);
  static SmallTalk parse(const core::YamlMap& map);

  /// One of `texts`, its groups drawn and {object} a topic, as a tidy sentence.
  std::string draw(const std::vector<TemplateText>& texts, core::Rng& rng) const;
};

}  // namespace ari_social_sim::dialogue
