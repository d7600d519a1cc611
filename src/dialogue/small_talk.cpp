#include "ari_social_sim/dialogue/small_talk.hpp"

namespace ari_social_sim::dialogue {
namespace {

constexpr const char* kTopic = "{object}";

std::vector<TemplateText> parse_texts(const core::YamlMap& map, const std::string& key,
                                      bool have_topics) {
  const auto sources = map.required<std::vector<std::string>>(key);
  if (sources.empty()) {
    map.fail(key, "at least one text", "[]");
  }
  std::vector<TemplateText> texts;
  for (size_t i = 0; i < sources.size(); ++i) {
    const std::string field = map.field_name(key) + "[" + std::to_string(i) + "]";
    if (!have_topics && sources[i].find(kTopic) != std::string::npos) {
      map.fail(key + "[" + std::to_string(i) + "]", "no {object} without a list of topics",
               "'" + sources[i] + "'");
    }
    texts.push_back(TemplateText::parse(sources[i], field));
  }
  return texts;
}

}  // namespace

SmallTalk SmallTalk::load(const std::string& file_path) {
  return parse(core::YamlMap::load_file(file_path));
}

SmallTalk SmallTalk::parse(const core::YamlMap& map) {
  SmallTalk talk;
  talk.topics = map.optional<std::vector<std::string>>("topics", {});
  const bool have_topics = !talk.topics.empty();
  talk.statements = parse_texts(map, "statements", have_topics);
  talk.questions = parse_texts(map, "questions", have_topics);
  talk.answers = parse_texts(map, "answers", have_topics);
  talk.backchannels = parse_texts(map, "backchannels", have_topics);
  map.finish();
  return talk;
}

std::string SmallTalk::draw(const std::vector<TemplateText>& texts, core::Rng& rng) const {
  std::string text = texts[rng.uniform_index(texts.size())].draw(rng);
  const size_t at = text.find(kTopic);
  if (at != std::string::npos) {
    text.replace(at, std::string(kTopic).size(), topics[rng.uniform_index(topics.size())]);
  }
  return tidy_sentence_text(text);
}

}  // namespace ari_social_sim::dialogue
