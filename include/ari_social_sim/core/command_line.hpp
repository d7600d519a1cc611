#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ari_social_sim/core/yaml_map.hpp"

namespace ari_social_sim::core {

/// A command-line option taking an integer, with its documented range. Each program declares one
/// constant per option, so that the check and the usage text read the same bounds, e.g.
///   constexpr core::IntegerOption kDialogues{"--dialogues", 1, 100000};
struct IntegerOption {
  const char* name;  ///< as typed, e.g. "--episodes"
  int64_t min;
  int64_t max;

  /// `[1, 100000]`.
  std::string range() const;
  /// The value of `text`, a decimal integer within [min, max]. Throws ConfigError naming the
  /// option, the range and the text otherwise, e.g. `--dialogues: expected an integer in
  /// [1, 100000], got '-1'`: a sign where none is allowed, overflow, surrounding spaces or
  /// trailing characters never wrap or truncate to some other number.
  int64_t parse(const std::string& text) const;
};

/// A command-line option taking a finite number within `bounds`.
struct NumberOption {
  const char* name;
  Bounds bounds;

  /// Throws ConfigError naming the option, e.g. `--stride: expected a finite number > 0, got
  /// 'nan'`, unless `text` is all of a finite number within the bounds.
  double parse(const std::string& text) const;
};

/// The value that follows the option `argv[i]`, stepping `i` over it. Throws ConfigError naming the
/// option when there is none (`--out: expected a value after it`) or it is empty (`--out: expected
/// a value, got ''`): an empty path or number never quietly stands for the default.
std::string option_value(int argc, char** argv, int& i);

/// Throws ConfigError `--frobnicate: unknown option, expected one of --out, --seed` unless
/// `option` is one of `known` (every option of the program, as typed). A program's option loop
/// calls it before option_value, so that an unknown option given last is called unknown, not a
/// known one missing its value.
void check_known_option(const std::string& option, const std::vector<std::string>& known);

/// Throws ConfigError (`--config: /tmp: expected a readable file, got a directory`) unless `path`
/// can be opened for reading and is not a directory.
void check_input_file(const char* option, const std::string& path);

/// Throws ConfigError naming the option unless `path` is an existing directory.
void check_input_directory(const char* option, const std::string& path);

/// Checks, before any work is done, that `path` can become a new output file: it is not a
/// directory, its folder exists and accepts new files, and it does not exist yet unless `replace`
/// (then the message says to pass --overwrite). Whether the folder accepts files is tried by
/// creating and removing a probe file in it: permission bits do not tell for root, nor on a
/// read-only mount. Throws ConfigError naming the option and the path.
void check_output_file(const char* option, const std::string& path, bool replace);

/// Creates the directory `path` with its parents when missing and checks that it accepts new
/// files (with a probe file, as check_output_file). Throws ConfigError naming the option when
/// `path` or one of its parents is a file, or it cannot be created or written.
void prepare_output_directory(const char* option, const std::string& path);

}  // namespace ari_social_sim::core
