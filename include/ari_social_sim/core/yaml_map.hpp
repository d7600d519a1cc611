#pragma once

#include <yaml-cpp/yaml.h>

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "ari_social_sim/core/bounds.hpp"

namespace ari_social_sim::core {

/// Largest YAML file YamlMap::load_file reads (bytes): 1 MiB. The shipped configs, worlds, scenes
/// and scenarios are under 6 KB; yaml-cpp holds a document as nodes hundreds of times larger than
/// its text (a 50 MB scene took 3.5 GB), so a bigger file is refused before it is read.
constexpr std::uintmax_t kMaxYamlFileBytes = std::uintmax_t{1024} * 1024;

/// Strict reader of one YAML mapping from a user's file or the parameter server.
///
/// Every read names its key; `finish()` rejects keys that were never read, so a typo cannot fall
/// back to a default. Failures throw core::ConfigError with the source, the field path, the value
/// found and the expectation, e.g.
///   `worlds/flat.yaml: objects[2].size: expected 2 numbers, each > 0, got [1.0, -2.0]`.
/// Supported value types: bool, int, unsigned, double, std::string, Eigen::Vector2d ([x, y]),
/// std::vector<double>, std::vector<unsigned>, std::vector<std::string>,
/// std::vector<Eigen::Vector2d> ([[x, y], ...]).
// NOLINTNEXTLINE(bugprone-exception-escape): the implicit assignments assign a YAML::Node, which
// may throw only for an invalid node; a YamlMap always holds a valid one.
class YamlMap {
 public:
  /// `source` names the file or parameter namespace; `path` the position inside it ("" at the top).
  YamlMap(const YAML::Node& node, std::string source, std::string path = "");

  /// Parses a file. Throws ConfigError naming the file, before reading it, if it does not exist,
  /// is a directory or anything but a regular file (a FIFO would block), cannot be opened, or is
  /// larger than kMaxYamlFileBytes; and after reading it if it is not YAML or not a mapping.
  static YamlMap load_file(const std::string& file_path);
  /// Parses YAML text (tests, service payloads); `source` is used in messages.
  static YamlMap parse(const std::string& text, const std::string& source);

  bool has(const std::string& key) const;

  template <class T>
  T required(const std::string& key, const Bounds& bounds = {}) const;
  template <class T>
  T optional(const std::string& key, const T& fallback, const Bounds& bounds = {}) const;

  /// A nested mapping under `key`.
  YamlMap map(const std::string& key) const;
  /// The mappings of a sequence under `key` (each named `key[i]` in messages). An absent key gives
  /// an empty list only when `allow_missing` is true.
  std::vector<YamlMap> list(const std::string& key, bool allow_missing = false) const;

  /// Throws ConfigError naming every key of this mapping that no call above has read.
  void finish() const;

  /// Throws ConfigError about `key` (which need not exist) with the given expectation and value.
  [[noreturn]] void fail(const std::string& key, const std::string& expectation,
                         const std::string& got) const;

  const std::string& source() const { return source_; }
  /// `source: path`, the way messages name this mapping (`source` at the top level).
  std::string where() const;
  /// `source: path.key`, the way messages name a field.
  std::string field_name(const std::string& key) const;

 private:
  YAML::Node value_node(const std::string& key) const;
  static std::string render(const YAML::Node& node);

  YAML::Node node_;
  std::string source_;
  std::string path_;
  mutable std::set<std::string> read_keys_;
};

}  // namespace ari_social_sim::core
