#pragma once

#include <map>
#include <set>
#include <string>
#include <vector>

#include "ari_social_sim/dialogue/domain.hpp"
#include "ari_social_sim/dialogue/nlg.hpp"

namespace ari_social_sim::audio {

/// Every sentence the dialogue's people can say with the template NLG: each human template's
/// surface forms (Nlg::template_texts), a pattern's `*` filled with each object of the domain,
/// lower case, without punctuation, each once, sorted.
std::vector<std::string> domain_sentences(const dialogue::Nlg& nlg, const dialogue::Domain& domain);

/// domain_sentences of the template NLG read from `templates_file` (NlgTemplates) over the domain
/// read from `domain_file`; throws core::ConfigError naming a file that does not load.
std::vector<std::string> read_domain_sentences(const std::string& templates_file,
                                               const std::string& domain_file);

/// The words of a pronunciation dictionary (cmudict's format: a word, then its phones; variants
/// as word(2) are the same word).
std::set<std::string> dictionary_words(const std::string& dictionary_path);

/// A trigram language model of `sentences` in ARPA text format, with absolute discounting (0.5)
/// and back-off weights, leaving out (and counting in `left_out`) the sentences with a word
/// outside `known_words`: pocketsphinx refuses a model with a word it cannot pronounce. (A JSGF
/// grammar of the same sentences, thousands of alternatives, decodes ten times slower than real
/// time and worse: pocketsphinx prunes its large finite-state search.)
std::string arpa_of(const std::vector<std::string>& sentences,
                    const std::set<std::string>& known_words, size_t* left_out);

/// arpa_of `sentences` against the dictionary of the pocketsphinx model in `model_dir`
/// (cmudict-en-us.dict, as RecognizerSettings::model_dir holds it).
std::string language_model_for(const std::vector<std::string>& sentences,
                               const std::string& model_dir, size_t* left_out);

/// `text` as the recogniser writes it: lower case, words of letters, digits and apostrophes.
std::string recognizer_words(const std::string& text);

}  // namespace ari_social_sim::audio
