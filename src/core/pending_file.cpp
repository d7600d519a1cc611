#include "ari_social_sim/core/pending_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "ari_social_sim/core/error.hpp"

namespace ari_social_sim::core {
namespace {

std::string folder_of(const std::string& path) {
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  return folder.empty() ? std::string(".") : folder.string();
}

std::string descriptor_path(int descriptor) {
  return "/proc/self/fd/" + std::to_string(descriptor);
}

// An unnamed file in `path`'s folder, or -1 where the file system (or a missing /proc, through
// which libraries open it) does not allow one.
int open_unnamed(const std::string& path) {
  const int descriptor = ::open(folder_of(path).c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0644);
  if (descriptor < 0) {
    return -1;
  }
  if (::access(descriptor_path(descriptor).c_str(), W_OK) != 0) {
    ::close(descriptor);
    return -1;
  }
  return descriptor;
}

std::string system_error() {
  return std::strerror(errno);
}

}  // namespace

PendingFile::PendingFile(std::string path, const std::string& fallback_suffix, Naming naming)
    : path_(std::move(path)), fallback_path_(path_ + fallback_suffix) {
  if (naming == Naming::unnamed_where_possible) {
    descriptor_ = open_unnamed(path_);
  }
  if (descriptor_ >= 0) {
    writable_path_ = descriptor_path(descriptor_);
    return;
  }
  // Created here, so that a folder that cannot be written is reported the same either way.
  const int fallback =
      ::open(fallback_path_.c_str(), O_CREAT | O_TRUNC | O_WRONLY | O_CLOEXEC, 0644);
  if (fallback < 0) {
    throw Error(path_ + ": cannot write " + fallback_path_ + " (" + system_error() + ")");
  }
  ::close(fallback);
  writable_path_ = fallback_path_;
}

PendingFile::~PendingFile() {
  if (descriptor_ >= 0) {
    ::close(descriptor_);  // an unpublished unnamed file is freed with its last descriptor
  } else if (!published_) {
    std::remove(fallback_path_.c_str());
  }
}

void PendingFile::publish() {
  if (descriptor_ >= 0) {
    link_unnamed();
  } else {
    std::error_code error;
    std::filesystem::rename(fallback_path_, path_, error);
    if (error) {
      throw Error(path_ + ": cannot rename " + fallback_path_ + " to it (" + error.message() + ")");
    }
  }
  published_ = true;
}

// linkat() never replaces a name, so a file already under `path` is replaced through the fallback
// name and a rename, which does so at once.
void PendingFile::link_unnamed() {
  const std::string source = descriptor_path(descriptor_);
  if (::linkat(AT_FDCWD, source.c_str(), AT_FDCWD, path_.c_str(), AT_SYMLINK_FOLLOW) == 0) {
    return;
  }
  if (errno != EEXIST) {
    throw Error(path_ + ": cannot name the written file (" + system_error() + ")");
  }
  std::remove(fallback_path_.c_str());
  if (::linkat(AT_FDCWD, source.c_str(), AT_FDCWD, fallback_path_.c_str(), AT_SYMLINK_FOLLOW) !=
          0 ||
      std::rename(fallback_path_.c_str(), path_.c_str()) != 0) {
    const std::string reason = system_error();
    std::remove(fallback_path_.c_str());
    throw Error(path_ + ": cannot replace it with the written file (" + reason + ")");
  }
}

}  // namespace ari_social_sim::core
