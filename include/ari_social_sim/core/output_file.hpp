#pragma once

#include <fstream>
#include <string>

namespace ari_social_sim::core {

/// An output file written under a temporary name, `<path>.part`, and renamed to `path` by
/// commit(): `path` holds either a complete output or what was there before, never half of one
/// (a failed run, a full disk, an exception). Destroyed uncommitted, it removes the .part file; a
/// process killed outright leaves it behind, under that name only.
class OutputFile {
 public:
  /// Opens `<path>.part` for writing. Throws ConfigError naming `option` and the path when it
  /// cannot be created.
  OutputFile(const std::string& option, std::string path);
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  std::ostream& stream() { return out_; }
  const std::string& path() const { return path_; }

  /// Flushes, closes and renames the file to `path` (replacing what was there). Throws core::Error
  /// naming the path when any write failed, the file then being removed.
  void commit();

 private:
  std::string path_;
  std::string part_path_;
  std::ofstream out_;
  bool committed_{false};
};

}  // namespace ari_social_sim::core
