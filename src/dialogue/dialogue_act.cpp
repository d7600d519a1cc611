#include "ari_social_sim/dialogue/dialogue_act.hpp"

#include <algorithm>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/dialogue/text.hpp"

namespace ari_social_sim::dialogue {
namespace {

bool is_name_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
}

// Reads `name ( name ( ... ) )` from one act's text. The chain form is all MPGT uses: one argument
// per level. Returns false on a malformed act; in repair mode unbalanced brackets are fixed.
class ActReader {
 public:
  ActReader(const std::string& text, bool repair) : text_(text), repair_(repair) {}

  bool read(std::vector<std::string>& names, int& repairs) {
    int open = 0;
    while (true) {
      std::string name;
      while (pos_ < text_.size() && is_name_char(text_[pos_])) {
        name += text_[pos_++];
      }
      if (name.empty()) {
        // `x()` ends the chain; anything else is malformed.
        if (names.empty() || pos_ >= text_.size() || text_[pos_] != ')') {
          return false;
        }
        break;
      }
      names.push_back(name);
      if (pos_ < text_.size() && text_[pos_] == '(') {
        ++pos_;
        ++open;
        continue;
      }
      break;
    }
    // Closing brackets: exactly `open` of them, then the end of the text.
    int closed = 0;
    while (pos_ < text_.size() && text_[pos_] == ')') {
      ++closed;
      ++pos_;
    }
    if (pos_ != text_.size()) {
      return false;
    }
    if (closed != open) {
      if (!repair_) {
        return false;
      }
      ++repairs;
    }
    // An outermost bare name (`request` without brackets) is not an act.
    return open > 0;
  }

 private:
  const std::string& text_;
  bool repair_;
  size_t pos_{0};
};

// Splits at `;` or `,` outside brackets.
std::vector<std::string> split_top_level(const std::string& text) {
  std::vector<std::string> parts;
  std::string current;
  int depth = 0;
  for (char c : text) {
    // `;` always separates acts; `,` only outside brackets (a surplus `)` may make depth < 0).
    if (c == ';' || (c == ',' && depth <= 0)) {
      parts.push_back(trim(current));
      current.clear();
      depth = 0;
      continue;
    }
    depth += c == '(' ? 1 : (c == ')' ? -1 : 0);
    current += c;
  }
  parts.push_back(trim(current));
  return parts;
}

DialogueAct read_one(const std::string& text, const std::string& source, bool repair,
                     int& repairs) {
  std::vector<std::string> names;
  ActReader reader(text, repair);
  if (!reader.read(names, repairs)) {
    throw core::ConfigError(source + ": dialogue act '" + text +
                            "': expected intent(slot(...(value))) such as "
                            "request(location(toilet)) or thank()");
  }
  const std::string intent = names.front();
  names.erase(names.begin());
  if (!repair && !is_known_intent(intent)) {
    throw core::ConfigError(source + ": dialogue act '" + text + "': unknown intent '" + intent +
                            "' (expected an MPGT intent such as request, inform, thank)");
  }
  return DialogueAct::from_path(intent, std::move(names));
}

}  // namespace

DialogueAct parse_pattern(const std::string& text, const std::string& source) {
  // The reader accepts names only; `*` goes through a stand-in that no act uses.
  const std::string stand_in = "x_wildcard_x";
  const auto swap = [](std::string s, const std::string& from, const std::string& to) {
    for (size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size())) {
      s.replace(at, from.size(), to);
    }
    return s;
  };
  DialogueAct act;
  try {
    act = parse_act(swap(text, "*", stand_in), source);
  } catch (const core::ConfigError& e) {
    throw core::ConfigError(swap(e.what(), stand_in, "*"));
  }
  for (std::string& slot : act.slots) {
    slot = slot == stand_in ? "*" : slot;
  }
  act.value = act.value == stand_in ? "*" : act.value;
  return act;
}

std::string DialogueAct::to_string() const {
  std::vector<std::string> names = path();
  std::string text = intent + "(";
  for (size_t i = 0; i < names.size(); ++i) {
    text += names[i];
    if (i + 1 < names.size()) {
      text += "(";
    }
  }
  text.append(names.empty() ? 1 : names.size(), ')');
  return text;
}

std::vector<std::string> DialogueAct::path() const {
  std::vector<std::string> names = slots;
  if (!value.empty()) {
    names.push_back(value);
  }
  return names;
}

DialogueAct DialogueAct::from_path(std::string intent, std::vector<std::string> path) {
  DialogueAct act;
  act.intent = std::move(intent);
  if (path.size() >= 2) {
    act.value = path.back();
    path.pop_back();
  }
  act.slots = std::move(path);
  return act;
}

bool DialogueAct::operator==(const DialogueAct& other) const {
  return intent == other.intent && slots == other.slots && value == other.value;
}

const std::vector<std::string>& mpgt_intents() {
  static const std::vector<std::string> kIntents = {
      "request",       "inform",     "thank",         "affirm",    "cant-help",
      "acknowledge",   "greet",      "offer-help",    "bye",       "incomplete-da",
      "suggest",       "disaffirm",  "give-feedback", "r-confirm", "p-repet",
      "accept-sugg",   "call-nurse", "r-repet",       "p-confirm", "change-volume",
      "youre-welcome", "cant-hear",  "r-paraph",      "p-paraph"};
  return kIntents;
}

bool is_known_intent(const std::string& intent) {
  const auto& intents = mpgt_intents();
  return std::find(intents.begin(), intents.end(), intent) != intents.end();
}

DialogueAct parse_act(const std::string& text, const std::string& source) {
  int repairs = 0;
  return read_one(trim(text), source, false, repairs);
}

std::vector<DialogueAct> parse_acts(const std::string& text, const std::string& source, bool repair,
                                    int* repairs) {
  std::vector<DialogueAct> acts;
  int count = 0;
  for (const std::string& part : split_top_level(text)) {
    if (part.empty()) {
      continue;
    }
    acts.push_back(read_one(part, source, repair, count));
  }
  if (repairs != nullptr) {
    *repairs += count;
  }
  return acts;
}

std::vector<std::string> parse_path(const std::string& text, const std::string& source) {
  const std::string trimmed = trim(text);
  if (trimmed.empty()) {
    return {};
  }
  try {
    return parse_act("request(" + trimmed + ")", source).path();
  } catch (const core::ConfigError&) {
    throw core::ConfigError(source +
                            ": expected a slot path such as toilet or "
                            "cafe(opening_times), got '" +
                            text + "'");
  }
}

std::string acts_to_string(const std::vector<DialogueAct>& acts) {
  std::string text;
  for (const DialogueAct& act : acts) {
    text += (text.empty() ? "" : "; ") + act.to_string();
  }
  return text;
}

}  // namespace ari_social_sim::dialogue
