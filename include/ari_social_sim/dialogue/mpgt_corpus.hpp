#pragma once

#include <string>
#include <vector>

#include "ari_social_sim/dialogue/dialogue_act.hpp"
#include "ari_social_sim/dialogue/goal.hpp"

namespace ari_social_sim::dialogue {

/// One line of an MPGT conversation: `Speaker: text # acts @ goal labels`.
struct CorpusUtterance {
  std::string speaker;  ///< seat code as written: ARI, LP, RP, LC, RC
  std::string role;     ///< ARI, patient or companion (mpgt_role)
  std::string text;
  std::vector<DialogueAct> acts;  ///< empty for an unannotated line
  std::vector<GoalLabel> goals;

  bool is_robot() const { return role == "ARI"; }
  /// Intent of the first act, or "none" for an unannotated line.
  std::string first_intent() const;
};

struct CorpusDialogue {
  std::string name;  ///< file name, e.g. convo7.txt
  std::vector<CorpusUtterance> utterances;
  int act_repairs{0};          ///< acts whose brackets were repaired
  int skipped_goal_labels{0};  ///< goal labels that could not be read
};

/// The 29 MPGT conversations. The annotations contain a few unbalanced brackets; they are repaired
/// on load and counted, so that a changed corpus shows up in the counts.
struct MpgtCorpus {
  std::vector<CorpusDialogue> dialogues;
  int act_repairs{0};          ///< sum over dialogues
  int skipped_goal_labels{0};  ///< sum over dialogues

  size_t utterance_count() const;
};

/// The name of the MPGT corpus among the public data sets (core::data_set_dir): scripts/
/// fetch_data.sh puts its convo*.txt files in $ARI_DATA_DIR/dialogue/mpgt.
inline constexpr const char* kMpgtDataSet = "dialogue/mpgt";

/// The environment variable ARI_MPGT_DIR when set and not empty, else "" (none pointed at).
std::string mpgt_dir_from_environment();

/// The corpus folder of a tool that cannot work without it: `given` (its --corpus DIR) when not
/// empty, else $ARI_MPGT_DIR, else the data set's folder. `needed_by` says what needs it
/// (`--compare`, `the fit`). Throws core::ConfigError when the folder is not a directory, naming
/// where the folder came from and, for the data set, how to fetch it
/// (core::missing_data_set_message).
std::string required_mpgt_dir(const std::string& given, const std::string& needed_by);

/// For the tools' --help: where the MPGT corpus comes from and how a tool finds it.
std::string mpgt_corpus_help();

/// Parses one conversation's text; `name` is used in messages. Throws core::ConfigError naming the
/// line when a line has no `Speaker:` prefix or an unknown speaker code.
CorpusDialogue parse_mpgt_dialogue(const std::string& text, const std::string& name);

/// Loads every `convo<N>.txt` in `dir`, ordered by N. Throws core::ConfigError if the directory
/// holds none or a file is malformed.
MpgtCorpus load_mpgt_corpus(const std::string& dir);

}  // namespace ari_social_sim::dialogue
