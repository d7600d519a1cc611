#pragma once

#include <string>

namespace ari_social_sim::core {

/// A file that gets its name only once it is complete.
///
/// Where the file system allows it (O_TMPFILE: ext4, xfs, btrfs, tmpfs), the file has no name at
/// all while it is written, so even a process killed outright (SIGKILL, an out-of-memory kill, a
/// SLURM task cancelled with --signal=KILL) leaves nothing behind: the kernel frees the unnamed
/// file with the process. Elsewhere (NFS and some cluster file systems) it is written as
/// `<path><fallback_suffix>` and renamed; a killed process then leaves that name, which the tools
/// clear when they resume.
///
/// Libraries that open files by name (rosbag, std::ofstream) write it through writable_path().
class PendingFile {
 public:
  enum class Naming {
    unnamed_where_possible,
    always_named,  // the fallback, wherever the file is (what NFS gets; tests use it)
  };

  /// Creates the file for `path`. Throws core::Error naming the path when it cannot.
  PendingFile(std::string path, const std::string& fallback_suffix,
              Naming naming = Naming::unnamed_where_possible);
  /// Removes the file unless publish() was called.
  ~PendingFile();
  PendingFile(const PendingFile&) = delete;
  PendingFile& operator=(const PendingFile&) = delete;

  /// The name to open the file by while it is written: /proc/self/fd/N for an unnamed file,
  /// `<path><fallback_suffix>` otherwise. Opening it truncates nothing but this file.
  const std::string& writable_path() const { return writable_path_; }
  /// Whether the file has a name while it is written (the fallback).
  bool named_while_written() const { return descriptor_ < 0; }

  /// Gives the file its name, `path` (replacing what was there at once). Call after whatever
  /// wrote it has closed it. Throws core::Error naming the path when it cannot.
  void publish();

 private:
  void link_unnamed();

  std::string path_;
  std::string fallback_path_;
  std::string writable_path_;
  int descriptor_{-1};
  bool published_{false};
};

}  // namespace ari_social_sim::core
