#include "ari_social_sim/core/progress_journal.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "ari_social_sim/core/error.hpp"

namespace ari_social_sim::core {
namespace {

constexpr const char* kDone = "done ";

std::string read_whole(const std::string& option, const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw ConfigError(option + ": " + path + ": cannot read the file (" + std::strerror(errno) +
                      ")");
  }
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

ProgressJournal ProgressJournal::start(const std::string& option, const std::string& path,
                                       const std::string& settings) {
  ProgressJournal journal;
  journal.path_ = path;
  journal.out_.open(path, std::ios::binary | std::ios::trunc);
  journal.out_ << settings << '\n' << std::flush;
  if (!journal.out_) {
    throw ConfigError(option + ": " + path + ": cannot write the file (" + std::strerror(errno) +
                      ")");
  }
  return journal;
}

ProgressJournal ProgressJournal::resume(const std::string& option, const std::string& path,
                                        const std::string& settings) {
  const std::string text = read_whole(option, path);
  const size_t header_end = text.find('\n');
  const std::string there = text.substr(0, header_end);
  if (header_end == std::string::npos || there != settings) {
    throw ConfigError(option + ": " + path + " was made with other settings:\n  there: " + there +
                      "\n  now:   " + settings +
                      "\npass the same options, or --overwrite to start again");
  }
  ProgressJournal journal;
  journal.path_ = path;
  size_t complete = header_end + 1;  // bytes up to the end of the last complete entry
  size_t entry_start = complete;
  for (size_t at = complete; at < text.size();) {
    const size_t end = text.find('\n', at);
    if (end == std::string::npos) {
      break;  // a line cut short
    }
    if (text.compare(at, std::strlen(kDone), kDone) == 0) {
      journal.kept_.push_back({text.substr(at + std::strlen(kDone), end - at - std::strlen(kDone)),
                               text.substr(entry_start, at - entry_start)});
      complete = end + 1;
      entry_start = complete;
    }
    at = end + 1;
  }
  journal.cut_short_ = complete < text.size();
  if (journal.cut_short_) {
    std::filesystem::resize_file(path, complete);
  }
  journal.out_.open(path, std::ios::binary | std::ios::app);
  if (!journal.out_) {
    throw ConfigError(option + ": " + path + ": cannot write the file (" + std::strerror(errno) +
                      ")");
  }
  return journal;
}

void ProgressJournal::add(const std::string& key, const std::string& lines) {
  if (lines.rfind(kDone, 0) == 0 || lines.find(std::string("\n") + kDone) != std::string::npos) {
    throw std::logic_error("ProgressJournal::add: a line of the entry starts with `done `");
  }
  // One write of the whole entry: a kill leaves at most this entry cut short.
  out_ << (lines + kDone + key + '\n') << std::flush;
  if (!out_) {
    throw Error(path_ + ": writing the progress of " + key + " failed (" + std::strerror(errno) +
                ")");
  }
}

void ProgressJournal::remove() {
  out_.close();
  std::filesystem::remove(path_);
}

void ProgressJournal::complete_as(const std::string& path) {
  out_.close();
  std::error_code error;
  std::filesystem::rename(path_, path, error);
  if (error) {
    throw Error(path + ": cannot rename " + path_ + " to it (" + error.message() + ")");
  }
  path_ = path;
}

}  // namespace ari_social_sim::core
