#pragma once

#include <fstream>
#include <string>
#include <vector>

namespace ari_social_sim::core {

/// What a batch tool has finished of an output it writes only at the end (a COCO file, a CSV),
/// kept beside it as `<output>.active` until the output is complete, so that `--resume` after a
/// signal or a crash keeps the finished units of work and runs only the missing ones.
///
/// The file is text: its first line, the settings the run was made with (one line, compared
/// byte for byte on --resume), then one entry per finished unit: its lines, then `done KEY`.
/// Each entry is written whole and flushed; one cut short (a process killed while writing it) is
/// cut off on --resume, its unit run again.
class ProgressJournal {
 public:
  struct Entry {
    std::string key;
    std::string lines;  // each ending with '\n'
  };

  /// Starts a new journal at `path` (replacing any), its first line `settings`. Throws
  /// ConfigError naming `option` and the path when it cannot be written.
  static ProgressJournal start(const std::string& option, const std::string& path,
                               const std::string& settings);
  /// Opens the journal at `path` to go on with it: checks that it was made with `settings`
  /// (ConfigError showing both lines otherwise), reads its complete entries and cuts off an entry
  /// cut short.
  static ProgressJournal resume(const std::string& option, const std::string& path,
                                const std::string& settings);

  ProgressJournal(ProgressJournal&&) = default;
  ProgressJournal& operator=(ProgressJournal&&) = default;

  const std::string& path() const { return path_; }
  /// The entries of an earlier run that resume() kept, in the order they were written.
  const std::vector<Entry>& kept() const { return kept_; }
  /// Whether resume() cut off an entry cut short.
  bool was_cut_short() const { return cut_short_; }

  /// Appends the entry of a finished unit, flushed. `lines` (each ending with '\n') must not
  /// hold a line starting with `done `. Throws Error naming the path when writing fails.
  void add(const std::string& key, const std::string& lines);
  /// Deletes the journal once the output it stood for is complete.
  void remove();
  /// Renames the journal to `path` once every unit is in it: a shard's complete records, which a
  /// merge reads with resume(). Throws Error naming both paths when it cannot.
  void complete_as(const std::string& path);

 private:
  ProgressJournal() = default;

  std::string path_;
  std::ofstream out_;
  std::vector<Entry> kept_;
  bool cut_short_{false};
};

}  // namespace ari_social_sim::core
