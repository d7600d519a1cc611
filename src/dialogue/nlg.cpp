#include "ari_social_sim/dialogue/nlg.hpp"

#include <set>
#include <sstream>

#include "ari_social_sim/core/error.hpp"

namespace ari_social_sim::dialogue {
namespace {

constexpr const char* kNone = "none";

template <class T>
const T& pick(const std::vector<T>& items, core::Rng& rng) {
  return items[rng.uniform_index(items.size())];
}

std::string replace_all(std::string text, const std::string& from, const std::string& to) {
  for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
    text.replace(at, from.size(), to);
  }
  return text;
}

// Lookup keys for an act, most specific first, each with the names {object} stands for:
// `request(location(toilet))`, `request(location(*))` (toilet), `request(*)` (location toilet).
std::vector<std::pair<std::string, std::vector<std::string>>> keys_of(const DialogueAct& act) {
  std::vector<std::pair<std::string, std::vector<std::string>>> keys;
  const std::vector<std::string> path = act.path();
  keys.emplace_back(act.to_string(), path);
  if (!path.empty()) {
    std::vector<std::string> prefix(path.begin(), path.end() - 1);
    prefix.emplace_back("*");
    keys.emplace_back(DialogueAct{act.intent, prefix, ""}.to_string(),
                      std::vector<std::string>{path.back()});
  }
  if (path.size() >= 2) {
    keys.emplace_back(act.intent + "(*)", path);
  }
  return keys;
}

}  // namespace

NlgMode parse_nlg_mode(const std::string& text, const std::string& field) {
  return core::parse_choice(text, kNlgModes, field);
}

NlgTemplates NlgTemplates::load(const std::string& file_path) {
  return parse(core::YamlMap::load_file(file_path));
}

NlgTemplates NlgTemplates::parse(const core::YamlMap& map) {
  NlgTemplates templates;
  for (const core::YamlMap& entry : map.list("words", true)) {
    templates.words[entry.required<std::string>("name")] = entry.required<std::string>("text");
    entry.finish();
  }
  for (const core::YamlMap& entry : map.list("templates")) {
    const std::string key = entry.required<std::string>("act");
    if (key != kNone) {
      parse_pattern(key, entry.field_name("act"));
    }
    const std::string speaker = entry.required<std::string>("speaker");
    if (speaker != "human" && speaker != "robot" && speaker != "any") {
      entry.fail("speaker", "human, robot or any", "'" + speaker + "'");
    }
    const auto sources = entry.required<std::vector<std::string>>("texts");
    if (sources.empty()) {
      entry.fail("texts", "at least one text", "[]");
    }
    std::vector<TemplateText> texts;
    for (size_t i = 0; i < sources.size(); ++i) {
      texts.push_back(TemplateText::parse(
          sources[i], entry.field_name("texts") + "[" + std::to_string(i) + "]"));
    }
    if (speaker != "robot") {
      auto& list = templates.human[key];
      list.insert(list.end(), texts.begin(), texts.end());
    }
    if (speaker != "human") {
      auto& list = templates.robot[key];
      list.insert(list.end(), texts.begin(), texts.end());
    }
    entry.finish();
  }
  map.finish();
  return templates;
}

Nlg::Nlg(NlgTemplates templates, const MpgtCorpus* corpus, NlgMode mode)
    : templates_(std::move(templates)), mode_(mode) {
  if (mode_ == NlgMode::kRetrieval && corpus == nullptr) {
    throw core::ConfigError("Nlg: retrieval mode needs the MPGT corpus");
  }
  if (corpus == nullptr) {
    return;
  }
  for (const CorpusDialogue& dialogue : corpus->dialogues) {
    for (const CorpusUtterance& u : dialogue.utterances) {
      const std::string key = u.acts.empty() ? std::string(kNone) : acts_to_string(u.acts);
      (u.is_robot() ? corpus_robot_ : corpus_human_)[key].push_back(u.text);
    }
  }
}

std::string Nlg::surface(const std::vector<std::string>& names) const {
  std::string text;
  for (const std::string& name : names) {
    const auto word = templates_.words.find(name);
    text += (text.empty() ? "" : " ") +
            (word != templates_.words.end() ? word->second : replace_all(name, "_", " "));
  }
  return text;
}

Nlg::TemplateMatch Nlg::find_template(bool robot, const DialogueAct& act) const {
  const auto& table = robot ? templates_.robot : templates_.human;
  for (auto& [key, names] : keys_of(act)) {
    const auto found = table.find(key);
    if (found != table.end()) {
      return {&found->second, std::move(names)};
    }
  }
  return {};
}

std::string Nlg::filled(const std::string& form, const std::vector<std::string>& names) const {
  return tidy_sentence_text(replace_all(form, "{object}", surface(names)));
}

std::string Nlg::from_template(bool robot, const DialogueAct* act, core::Rng& rng) const {
  if (act == nullptr) {
    const auto& table = robot ? templates_.robot : templates_.human;
    const auto found = table.find(kNone);
    return found != table.end() ? filled(pick(found->second, rng).draw(rng), {}) : "Hmm.";
  }
  const TemplateMatch match = find_template(robot, *act);
  if (match.texts != nullptr) {
    return filled(pick(*match.texts, rng).draw(rng), match.names);
  }
  // No template: say the intent and its path in words rather than nothing.
  return replace_all(act->intent, "-", " ") + " " + surface(act->path()) + ".";
}

std::vector<DialogueAct> Nlg::own_template_acts(bool robot) const {
  std::vector<DialogueAct> acts;
  for (const auto& entry : robot ? templates_.robot : templates_.human) {
    if (entry.first.find('*') == std::string::npos && entry.first != "none") {
      acts.push_back(parse_act(entry.first, robot ? "robot template" : "human template"));
    }
  }
  return acts;
}

std::vector<std::string> Nlg::template_texts(bool robot, const DialogueAct& act) const {
  const TemplateMatch match = find_template(robot, act);
  std::vector<std::string> texts;
  if (match.texts != nullptr) {
    for (const TemplateText& text : *match.texts) {
      for (const std::string& form : text.expand(kMaxFormsPerText)) {
        texts.push_back(filled(form, match.names));
      }
    }
  }
  return texts;
}

std::string Nlg::realise(bool robot, const std::vector<DialogueAct>& acts, core::Rng& rng) const {
  const auto& index = robot ? corpus_robot_ : corpus_human_;
  if (mode_ == NlgMode::kRetrieval) {
    const auto found = index.find(acts.empty() ? std::string(kNone) : acts_to_string(acts));
    if (found != index.end()) {
      return pick(found->second, rng);
    }
  }
  if (acts.empty()) {
    return from_template(robot, nullptr, rng);
  }
  // Act by act: a real single-act utterance when retrieving, else the template.
  std::string text;
  for (const DialogueAct& act : acts) {
    std::string part;
    if (mode_ == NlgMode::kRetrieval) {
      const auto found = index.find(act.to_string());
      if (found != index.end()) {
        part = pick(found->second, rng);
      }
    }
    if (part.empty()) {
      part = from_template(robot, &act, rng);
    }
    text += (text.empty() ? "" : " ") + part;
  }
  return text;
}

std::vector<std::string> Nlg::vocabulary() const {
  std::set<std::string> words;
  auto add_text = [&words](const std::string& text) {
    std::istringstream in(text);
    std::string word;
    while (in >> word) {
      if (word.find('{') == std::string::npos) {
        words.insert(word);
      }
    }
  };
  for (const auto* table : {&templates_.human, &templates_.robot}) {
    for (const auto& entry : *table) {
      for (const TemplateText& text : entry.second) {
        for (const std::string& form : text.expand(kMaxFormsPerText)) {
          add_text(tidy_sentence_text(form));
        }
      }
    }
  }
  for (const auto* table : {&corpus_human_, &corpus_robot_}) {
    for (const auto& entry : *table) {
      for (const std::string& text : entry.second) {
        add_text(text);
      }
    }
  }
  return {words.begin(), words.end()};
}

}  // namespace ari_social_sim::dialogue
