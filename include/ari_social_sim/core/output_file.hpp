#pragma once

#include <fstream>
#include <string>

#include "ari_social_sim/core/pending_file.hpp"

namespace ari_social_sim::core {

/// An output file that appears under its name, `path`, only when commit() has written it whole:
/// `path` holds either a complete output or what was there before, never half of one (a failed
/// run, a full disk, an exception, a killed process). While written it has no name, or
/// `<path>.part` where the file system cannot do without one (core::PendingFile). Destroyed
/// uncommitted, it leaves nothing.
class OutputFile {
 public:
  /// Opens the file for writing. Throws ConfigError naming `option` and the path when it cannot
  /// be created.
  OutputFile(const std::string& option, std::string path,
             PendingFile::Naming naming = PendingFile::Naming::unnamed_where_possible);
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  std::ostream& stream() { return out_; }
  const std::string& path() const { return path_; }

  /// Flushes, closes and names the file `path` (replacing what was there). Throws core::Error
  /// naming the path when any write failed, the file then being dropped.
  void commit();

 private:
  std::string path_;
  PendingFile pending_;
  std::ofstream out_;
};

}  // namespace ari_social_sim::core
