#pragma once

// A full disk for the tests that a write failure is reported: a file size limit fails the writes
// past it (EFBIG) as a full disk fails them (ENOSPC). Programs the test starts meanwhile inherit
// it. Works however the file is written, named or not (core::PendingFile).

#include <sys/resource.h>

#include <csignal>

namespace ari_social_sim::test {

class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    getrlimit(RLIMIT_FSIZE, &before_);
    signal_before_ = std::signal(SIGXFSZ, SIG_IGN);  // else the writer is killed, not refused
    rlimit limit = before_;
    limit.rlim_cur = bytes;
    setrlimit(RLIMIT_FSIZE, &limit);
  }
  ~FileSizeLimit() {
    setrlimit(RLIMIT_FSIZE, &before_);
    std::signal(SIGXFSZ, signal_before_);
  }
  FileSizeLimit(const FileSizeLimit&) = delete;
  FileSizeLimit& operator=(const FileSizeLimit&) = delete;

 private:
  rlimit before_{};
  void (*signal_before_)(int){nullptr};
};

}  // namespace ari_social_sim::test
