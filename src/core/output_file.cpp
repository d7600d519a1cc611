#include "ari_social_sim/core/output_file.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "ari_social_sim/core/error.hpp"

namespace ari_social_sim::core {

OutputFile::OutputFile(const std::string& option, std::string path)
    : path_(std::move(path)), part_path_(path_ + ".part"), out_(part_path_) {
  if (!out_) {
    throw ConfigError(option + ": " + path_ + ": cannot write " + part_path_ + " (" +
                      std::strerror(errno) + ")");
  }
}

OutputFile::~OutputFile() {
  if (!committed_) {
    out_.close();
    std::error_code ignored;
    std::filesystem::remove(part_path_, ignored);
  }
}

void OutputFile::commit() {
  out_.flush();
  const bool written = static_cast<bool>(out_);
  out_.close();
  if (!written || out_.fail()) {
    throw Error(path_ + ": writing failed (" + std::string(std::strerror(errno)) +
                "); nothing was written under that name");
  }
  std::error_code error;
  std::filesystem::rename(part_path_, path_, error);
  if (error) {
    throw Error(path_ + ": cannot rename " + part_path_ + " to it (" + error.message() + ")");
  }
  committed_ = true;
}

}  // namespace ari_social_sim::core
