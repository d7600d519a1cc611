#pragma once

#include <optional>
#include <string>
#include <vector>

#include "ari_social_sim/scenario/script.hpp"

namespace ari_social_sim::scenario {

/// ARI's understanding of what it heard in a scripted scene: a recogniser's transcript is taken
/// for the script's human line it is nearest to (the cosine of their word sets), when near enough.
/// A scene's script knows every line its people can say, so this is the whole NLU it needs; a
/// transcript with a few words wrong still lands on its line, and one with none of a line's words
/// on none.
class HeardLines {
 public:
  /// The lines of `script` said by humans (say actions), with their acts.
  explicit HeardLines(const Script& script);

  /// The act of the line `transcript` is taken for; none when no line shares at least
  /// kMinSimilarity of its words with it.
  std::optional<std::string> act_of(const std::string& transcript) const;

  /// Whether a human line's act matches `pattern` (act_matches).
  bool has_act(const std::string& pattern) const;

  /// The texts of the human lines, each once, in the order the script gives them (the sentences
  /// a recogniser's language model for the scene should know).
  std::vector<std::string> texts() const;

  static constexpr double kMinSimilarity = 0.5;

 private:
  struct Line {
    std::vector<std::string> words;  // sorted, each once
    std::string text;
    std::string act;
  };
  std::vector<Line> lines_;
};

}  // namespace ari_social_sim::scenario
