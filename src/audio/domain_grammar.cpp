#include "ari_social_sim/audio/domain_grammar.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/dialogue/text.hpp"

namespace ari_social_sim::audio {
namespace {

// The acts a template key stands for: itself, or for a pattern each object of the domain in
// place of `*`.
std::vector<dialogue::DialogueAct> acts_of_key(const std::string& key,
                                               const dialogue::Domain& domain) {
  if (key == "none") {
    return {};
  }
  if (key.find('*') == std::string::npos) {
    return {dialogue::parse_act(key, "nlg template key")};
  }
  const dialogue::DialogueAct pattern = dialogue::parse_pattern(key, "nlg template key");
  std::vector<dialogue::DialogueAct> acts;
  for (const dialogue::PredicateSpec& predicate : domain.predicates()) {
    for (const dialogue::DomainObject& object : predicate.objects) {
      acts.push_back(dialogue::instantiate_pattern(pattern, object.path));
    }
  }
  return acts;
}

using Gram = std::vector<std::string>;

// Absolute discounting: what each seen n-gram gives up for the unseen ones.
constexpr double kDiscount = 0.5;

double log10_of(double p) {
  return p > 0.0 ? std::log10(p) : -99.0;
}

// The n-gram counts of a set of sentences and their back-off trigram model.
class NgramCounts {
 public:
  void add(const std::vector<std::string>& words) {
    for (size_t i = 0; i < words.size(); ++i) {
      ++grams_[0][{words[i]}];
      if (i >= 1) {
        ++grams_[1][{words[i - 1], words[i]}];
      }
      if (i >= 2) {
        ++grams_[2][{words[i - 2], words[i - 1], words[i]}];
      }
    }
  }

  std::string arpa() {
    compute();
    std::ostringstream out;
    out << "\\data\\\n";
    for (size_t n = 0; n < 3; ++n) {
      out << "ngram " << n + 1 << "=" << grams_[n].size() << "\n";
    }
    for (size_t n = 0; n < 3; ++n) {
      out << "\n\\" << n + 1 << "-grams:\n";
      for (const auto& [gram, count] : grams_[n]) {
        out << log10_of(probability_[n][gram]);
        for (const std::string& word : gram) {
          out << " " << word;
        }
        const auto weight = n < 2 ? backoff_[n].find(gram) : backoff_[0].end();
        if (n < 2 && weight != backoff_[n].end()) {
          out << " " << std::log10(std::max(weight->second, 1e-12));
        }
        out << "\n";
      }
    }
    out << "\n\\end\\\n";
    return out.str();
  }

 private:
  // p(w | history) under the model of order `n` (0: unigram), backing off where unseen.
  double backed_off(size_t n, const Gram& gram) const {
    const auto seen = probability_[n].find(gram);
    if (seen != probability_[n].end()) {
      return seen->second;
    }
    if (n == 0) {
      return 0.0;
    }
    const Gram history(gram.begin(), gram.end() - 1);
    const auto weight = backoff_[n - 1].find(history);
    const double bow = weight == backoff_[n - 1].end() ? 1.0 : weight->second;
    return bow * backed_off(n - 1, Gram(gram.begin() + 1, gram.end()));
  }

  void compute() {
    double total = 0.0;
    for (const auto& [gram, count] : grams_[0]) {
      total += gram[0] == "<s>" ? 0.0 : count;
    }
    for (const auto& [gram, count] : grams_[0]) {
      probability_[0][gram] = gram[0] == "<s>" ? 0.0 : count / total;
    }
    for (size_t n = 1; n < 3; ++n) {
      std::map<Gram, double> history_counts;
      for (const auto& [gram, count] : grams_[n]) {
        history_counts[Gram(gram.begin(), gram.end() - 1)] += count;
      }
      std::map<Gram, std::pair<double, double>> mass;  // history -> (seen p, their lower p)
      for (const auto& [gram, count] : grams_[n]) {
        const Gram history(gram.begin(), gram.end() - 1);
        const double p = (count - kDiscount) / history_counts[history];
        probability_[n][gram] = p;
        mass[history].first += p;
        mass[history].second += backed_off(n - 1, Gram(gram.begin() + 1, gram.end()));
      }
      for (const auto& [history, seen] : mass) {
        backoff_[n - 1][history] = (1.0 - seen.first) / std::max(1.0 - seen.second, 1e-9);
      }
    }
  }

  std::array<std::map<Gram, double>, 3> grams_;
  std::array<std::map<Gram, double>, 3> probability_;
  std::array<std::map<Gram, double>, 2> backoff_;
};

}  // namespace

std::string recognizer_words(const std::string& text) {
  std::string out;
  bool space = true;
  for (const char c : text) {
    const unsigned char u = static_cast<unsigned char>(c);
    if (std::isalnum(u) || c == '\'') {
      out += static_cast<char>(std::tolower(u));
      space = false;
    } else if (!space) {
      out += ' ';
      space = true;
    }
  }
  while (!out.empty() && out.back() == ' ') {
    out.pop_back();
  }
  return out;
}

std::vector<std::string> domain_sentences(const dialogue::Nlg& nlg,
                                          const dialogue::Domain& domain) {
  std::set<std::string> sentences;
  for (const auto& [key, texts] : nlg.templates().human) {
    std::vector<std::string> forms;
    if (key == "none") {
      for (const dialogue::TemplateText& text : texts) {
        const std::vector<std::string> expanded = text.expand(dialogue::kMaxFormsPerText);
        forms.insert(forms.end(), expanded.begin(), expanded.end());
      }
    }
    for (const dialogue::DialogueAct& act : acts_of_key(key, domain)) {
      const std::vector<std::string> texts_of_act = nlg.template_texts(false, act);
      forms.insert(forms.end(), texts_of_act.begin(), texts_of_act.end());
    }
    for (const std::string& form : forms) {
      const std::string words = recognizer_words(form);
      if (!words.empty()) {
        sentences.insert(words);
      }
    }
  }
  return {sentences.begin(), sentences.end()};
}

std::set<std::string> dictionary_words(const std::string& dictionary_path) {
  std::ifstream in(dictionary_path);
  if (!in) {
    throw core::ConfigError(dictionary_path + ": cannot read the pronunciation dictionary");
  }
  std::set<std::string> words;
  std::string line;
  while (std::getline(in, line)) {
    std::string word = line.substr(0, line.find(' '));
    word = word.substr(0, word.find('('));
    if (!word.empty()) {
      words.insert(word);
    }
  }
  return words;
}

std::string arpa_of(const std::vector<std::string>& sentences,
                    const std::set<std::string>& known_words, size_t* left_out) {
  NgramCounts counts;
  *left_out = 0;
  for (const std::string& sentence : sentences) {
    std::vector<std::string> words{"<s>"};
    for (std::string& word : dialogue::split_words(sentence)) {
      words.push_back(std::move(word));
    }
    words.emplace_back("</s>");
    const bool known = std::all_of(words.begin() + 1, words.end() - 1,
                                   [&](const std::string& w) { return known_words.count(w) > 0; });
    if (!known) {
      ++*left_out;
      continue;
    }
    counts.add(words);
  }
  return counts.arpa();
}

std::vector<std::string> read_domain_sentences(const std::string& templates_file,
                                               const std::string& domain_file) {
  const dialogue::Nlg nlg(dialogue::NlgTemplates::load(templates_file), nullptr,
                          dialogue::NlgMode::kTemplate);
  return domain_sentences(nlg, dialogue::Domain::load(domain_file));
}

std::string language_model_for(const std::vector<std::string>& sentences,
                               const std::string& model_dir, size_t* left_out) {
  return arpa_of(sentences, dictionary_words(model_dir + "/cmudict-en-us.dict"), left_out);
}

}  // namespace ari_social_sim::audio
