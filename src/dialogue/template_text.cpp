#include "ari_social_sim/dialogue/template_text.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <string_view>

#include "ari_social_sim/core/error.hpp"

namespace ari_social_sim::dialogue {
namespace {

constexpr std::string_view kObjectPlaceholder = "{object}";

bool is_sentence_end(char c) {
  return c == '.' || c == '?' || c == '!';
}

bool is_punctuation(char c) {
  return is_sentence_end(c) || c == ',' || c == ':' || c == ';';
}

// Reads the text left to right; the parts so far, the open group and the run being written.
class TemplateParser {
 public:
  TemplateParser(const std::string& text, const std::string& field) : text_(text), field_(field) {}

  std::vector<std::vector<std::string>> parse() {
    for (size_t at = 0; at < text_.size(); ++at) {
      const char c = text_[at];
      if (c == '[') {
        open_group(at);
      } else if (c == '|') {
        next_alternative(at);
      } else if (c == ']') {
        close_group(at);
      } else if (c == '{') {
        at = placeholder(at);
      } else if (c == '}') {
        fail("'}' only as the end of {object}", at);
      } else {
        run_ += c;
      }
    }
    if (in_group_) {
      fail("']' to close the '[' at character " + std::to_string(group_start_ + 1), text_.size());
    }
    end_literal();
    return std::move(parts_);
  }

 private:
  [[noreturn]] void fail(const std::string& expectation, size_t at) const {
    throw core::ConfigError(field_ + ": expected " + expectation + " (at character " +
                            std::to_string(at + 1) + "), got '" + text_ + "'");
  }

  void end_literal() {
    if (!run_.empty()) {
      parts_.push_back({std::move(run_)});
      run_.clear();
    }
  }

  void open_group(size_t at) {
    if (in_group_) {
      fail("no '[' inside [...] (groups do not nest)", at);
    }
    end_literal();
    in_group_ = true;
    group_start_ = at;
  }

  void next_alternative(size_t at) {
    if (!in_group_) {
      fail("'|' only between alternatives inside [...]", at);
    }
    group_.push_back(std::move(run_));
    run_.clear();
  }

  void close_group(size_t at) {
    if (!in_group_) {
      fail("']' only to close a '['", at);
    }
    group_.push_back(std::move(run_));
    run_.clear();
    if (group_.size() < 2) {
      fail("two or more alternatives separated by '|' in [...] ([a|] makes a optional)", at);
    }
    parts_.push_back(std::move(group_));
    group_.clear();
    in_group_ = false;
  }

  // The placeholder starting at `at`; returns the index of its last character.
  size_t placeholder(size_t at) {
    if (text_.compare(at, kObjectPlaceholder.size(), kObjectPlaceholder) != 0) {
      fail("{object}, the only placeholder", at);
    }
    run_ += kObjectPlaceholder;
    return at + kObjectPlaceholder.size() - 1;
  }

  const std::string& text_;
  const std::string& field_;
  std::vector<std::vector<std::string>> parts_;
  std::vector<std::string> group_;
  std::string run_;
  bool in_group_{false};
  size_t group_start_{0};
};

}  // namespace

TemplateText TemplateText::parse(const std::string& text, const std::string& field) {
  TemplateText parsed;
  parsed.parts_ = TemplateParser(text, field).parse();
  return parsed;
}

std::string TemplateText::draw(core::Rng& rng) const {
  std::string text;
  for (const std::vector<std::string>& part : parts_) {
    text += part.size() == 1 ? part.front() : part[rng.uniform_index(part.size())];
  }
  return text;
}

size_t TemplateText::form_count() const {
  size_t count = 1;
  for (const std::vector<std::string>& part : parts_) {
    if (count > SIZE_MAX / part.size()) {
      return SIZE_MAX;
    }
    count *= part.size();
  }
  return count;
}

std::vector<std::string> TemplateText::expand(size_t cap) const {
  std::vector<std::string> texts;
  const size_t count = form_count();
  if (count <= cap) {
    // Mixed-radix counting over the groups, the last group fastest.
    std::vector<size_t> choice(parts_.size(), 0);
    for (size_t n = 0; n < count; ++n) {
      std::string text;
      for (size_t p = 0; p < parts_.size(); ++p) {
        text += parts_[p][choice[p]];
      }
      texts.push_back(std::move(text));
      for (size_t p = parts_.size(); p-- > 0;) {
        if (++choice[p] < parts_[p].size()) {
          break;
        }
        choice[p] = 0;
      }
    }
    return texts;
  }
  size_t widest = 1;
  for (const std::vector<std::string>& part : parts_) {
    widest = std::max(widest, part.size());
  }
  for (size_t i = 0; i < widest; ++i) {
    std::string text;
    for (const std::vector<std::string>& part : parts_) {
      text += part[i % part.size()];
    }
    texts.push_back(std::move(text));
  }
  return texts;
}

std::string tidy_sentence_text(const std::string& text) {
  std::string tidy;
  for (char c : text) {
    const bool space = std::isspace(static_cast<unsigned char>(c)) != 0;
    if (space && (tidy.empty() || tidy.back() == ' ')) {
      continue;
    }
    if (is_punctuation(c) && !tidy.empty() && tidy.back() == ' ') {
      tidy.pop_back();
    }
    tidy += space ? ' ' : c;
  }
  if (!tidy.empty() && tidy.back() == ' ') {
    tidy.pop_back();
  }
  bool sentence_start = true;
  for (char& c : tidy) {
    const auto u = static_cast<unsigned char>(c);
    if (sentence_start && std::isalpha(u)) {
      c = static_cast<char>(std::toupper(u));
    }
    if (is_sentence_end(c)) {
      sentence_start = true;
    } else if (!std::isspace(u)) {
      sentence_start = false;
    }
  }
  return tidy;
}

}  // namespace ari_social_sim::dialogue
