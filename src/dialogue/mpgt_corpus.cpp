#include "ari_social_sim/dialogue/mpgt_corpus.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/text_file.hpp"
#include "ari_social_sim/dialogue/text.hpp"

#ifndef ARI_MPGT_DIR
#error "ARI_MPGT_DIR: the build gives the MPGT corpus's folder (cmake/dialogue.cmake)"
#endif

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

std::string default_mpgt_dir() {
  const char* from_environment = std::getenv("ARI_MPGT_DIR");
  if (from_environment != nullptr && *from_environment != '\0') {
    return from_environment;
  }
  return ARI_MPGT_DIR;
}

std::string mpgt_corpus_help() {
  return "  MPGT corpus: the folder of the convo*.txt files of the public MPGT corpus,\n"
         "    https://github.com/AddleseeHQ/mpgt-eval (MIT licence; docs/dialogue.md), which is\n"
         "    not part of this repository. Given no folder, the tool reads $ARI_MPGT_DIR, else\n"
         "    the folder set at build time (cmake -DARI_MPGT_DIR=DIR).\n";
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
    constexpr std::uintmax_t kMaxConversationBytes = 1024 * 1024;
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
