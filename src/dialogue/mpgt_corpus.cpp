#include "ari_social_sim/dialogue/mpgt_corpus.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "ari_social_sim/core/command_line.hpp"
#include "ari_social_sim/core/data_sets.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/text_file.hpp"
#include "ari_social_sim/dialogue/text.hpp"

namespace ari_social_sim::dialogue {
namespace {

// Number N of `convoN.txt`, or -1 for any other file name.
int conversation_number(const std::string& file_name) {
  const std::string prefix = "convo";
  const std::string suffix = ".txt";
  if (file_name.size() <= prefix.size() + suffix.size() || file_name.rfind(prefix, 0) != 0 ||
      file_name.substr(file_name.size() - suffix.size()) != suffix) {
    return -1;
  }
  const std::string digits =
      file_name.substr(prefix.size(), file_name.size() - prefix.size() - suffix.size());
  if (digits.empty() || !std::all_of(digits.begin(), digits.end(), ::isdigit)) {
    return -1;
  }
  return std::stoi(digits);
}

}  // namespace

std::string CorpusUtterance::first_intent() const {
  return acts.empty() ? std::string("none") : acts.front().intent;
}

size_t MpgtCorpus::utterance_count() const {
  size_t count = 0;
  for (const CorpusDialogue& dialogue : dialogues) {
    count += dialogue.utterances.size();
  }
  return count;
}

std::string mpgt_dir_from_environment() {
  const char* from_environment = std::getenv("ARI_MPGT_DIR");
  return from_environment != nullptr ? from_environment : "";
}

std::string required_mpgt_dir(const std::string& given, const std::string& needed_by) {
  if (!given.empty()) {
    core::check_input_directory("--corpus", given);
    return given;
  }
  std::string from_environment = mpgt_dir_from_environment();
  if (!from_environment.empty()) {
    core::check_input_directory("$ARI_MPGT_DIR", from_environment);
    return from_environment;
  }
  if (!core::data_set_present(kMpgtDataSet)) {
    throw core::ConfigError(needed_by +
                            " needs the MPGT corpus, and none was given (no --corpus DIR, "
                            "ARI_MPGT_DIR not set): " +
                            core::missing_data_set_message(kMpgtDataSet));
  }
  return core::data_set_dir(kMpgtDataSet);
}

std::string mpgt_corpus_help() {
  return "  MPGT corpus: the folder of the convo*.txt files of the public MPGT corpus,\n"
         "    https://github.com/AddleseeHQ/mpgt-eval (MIT licence; docs/dialogue.md), which is\n"
         "    not part of this repository. scripts/fetch_data.sh fetches it into\n"
         "    $ARI_DATA_DIR/dialogue/mpgt. Where it is needed, the tool reads --corpus DIR, else\n"
         "    $ARI_MPGT_DIR when set, else $ARI_DATA_DIR/dialogue/mpgt (ARI_DATA_DIR defaults to\n"
         "    ~/.local/share/ari_social_sim/data).\n";
}

CorpusDialogue parse_mpgt_dialogue(const std::string& text, const std::string& name) {
  // Line format: `Speaker: utterance # act; act @ G(...); AG(...)`; `#` and `@` are optional.
  CorpusDialogue dialogue;
  dialogue.name = name;
  std::istringstream lines(text);
  std::string line;
  int line_number = 0;
  while (std::getline(lines, line)) {
    ++line_number;
    line = trim(line);
    if (line.empty()) {
      continue;
    }
    const std::string where = name + ":" + std::to_string(line_number);
    const size_t colon = line.find(':');
    if (colon == std::string::npos) {
      throw core::ConfigError(where + ": expected 'Speaker: utterance', got '" + line + "'");
    }
    CorpusUtterance utterance;
    utterance.speaker = trim(line.substr(0, colon));
    utterance.role = mpgt_role(utterance.speaker);
    if (utterance.role.empty()) {
      throw core::ConfigError(where + ": speaker '" + utterance.speaker +
                              "': expected ARI, LP, RP, LC or RC");
    }
    std::string rest = line.substr(colon + 1);
    const size_t at = rest.find('@');
    if (at != std::string::npos) {
      utterance.goals = parse_mpgt_goal_labels(rest.substr(at + 1), &dialogue.skipped_goal_labels);
      rest = rest.substr(0, at);
    }
    const size_t hash = rest.find('#');
    if (hash != std::string::npos) {
      utterance.acts = parse_acts(rest.substr(hash + 1), where, true, &dialogue.act_repairs);
      rest = rest.substr(0, hash);
    }
    utterance.text = trim(rest);
    dialogue.utterances.push_back(std::move(utterance));
  }
  return dialogue;
}

MpgtCorpus load_mpgt_corpus(const std::string& dir) {
  namespace fs = std::filesystem;
  std::vector<std::pair<int, fs::path>> files;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(dir, error)) {
    const int number = conversation_number(entry.path().filename().string());
    if (number >= 0) {
      files.emplace_back(number, entry.path());
    }
  }
  if (error || files.empty()) {
    throw core::ConfigError(dir + ": expected a directory of MPGT conversations convo<N>.txt" +
                            (error ? " (" + error.message() + ")" : std::string(", found none")));
  }
  std::sort(files.begin(), files.end());
  MpgtCorpus corpus;
  for (const auto& [number, path] : files) {
    // The corpus's conversations are a few kilobytes each.
    constexpr std::uintmax_t kMaxConversationBytes = std::uintmax_t{1024} * 1024;
    CorpusDialogue dialogue = parse_mpgt_dialogue(
        core::read_text_file(path.string(), "an MPGT conversation", kMaxConversationBytes),
        path.filename().string());
    corpus.act_repairs += dialogue.act_repairs;
    corpus.skipped_goal_labels += dialogue.skipped_goal_labels;
    corpus.dialogues.push_back(std::move(dialogue));
  }
  return corpus;
}

}  // namespace ari_social_sim::dialogue
