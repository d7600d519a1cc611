#include "ari_social_sim/core/output_file.hpp"

#include <cerrno>
#include <cstring>

#include "ari_social_sim/core/error.hpp"

namespace ari_social_sim::core {
namespace {

PendingFile open_pending(const std::string& option, const std::string& path,
                         PendingFile::Naming naming) {
  try {
    return PendingFile(path, ".part", naming);
  } catch (const Error& e) {
    throw ConfigError(option + ": " + e.what());
  }
}

}  // namespace

OutputFile::OutputFile(const std::string& option, std::string path, PendingFile::Naming naming)
    : path_(std::move(path)),
      pending_(open_pending(option, path_, naming)),
      out_(pending_.writable_path()) {
  if (!out_) {
    throw ConfigError(option + ": " + path_ + ": cannot write " + pending_.writable_path() + " (" +
                      std::strerror(errno) + ")");
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
  pending_.publish();
}

}  // namespace ari_social_sim::core
