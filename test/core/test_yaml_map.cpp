#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/yaml_map.hpp"

namespace ari_social_sim::core {
namespace {

// Expects `body` to throw ConfigError whose message contains every fragment.
template <class F>
void expect_config_error(F body, const std::vector<std::string>& fragments) {
  try {
    body();
    FAIL() << "no ConfigError thrown";
  } catch (const ConfigError& e) {
    for (const std::string& fragment : fragments) {
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos)
          << "'" << fragment << "' missing from: " << e.what();
    }
  }
}

TEST(YamlMap, ReadsTypedValuesAndDefaults) {
  const YamlMap map = YamlMap::parse("a: 1.5\nb: [2, 3]\nname: x\nflag: true\n", "t.yaml");
  EXPECT_DOUBLE_EQ(map.required<double>("a", positive()), 1.5);
  EXPECT_EQ(map.required<Eigen::Vector2d>("b"), Eigen::Vector2d(2, 3));
  EXPECT_EQ(map.required<std::string>("name"), "x");
  EXPECT_TRUE(map.required<bool>("flag"));
  EXPECT_EQ(map.optional<int>("missing", 4), 4);
  EXPECT_NO_THROW(map.finish());
}

TEST(YamlMap, ErrorsNameSourceFieldValueAndExpectation) {
  const YamlMap map = YamlMap::parse("objects:\n  - {size: [1.0, -2.0]}\n", "w.yaml");
  const YamlMap item = map.list("objects")[0];
  expect_config_error([&] { item.required<Eigen::Vector2d>("size", positive()); },
                      {"w.yaml", "objects[0].size", "> 0", "[1.0, -2.0]"});
  expect_config_error([&] { item.required<double>("radius"); }, {"objects[0].radius", "required"});
  expect_config_error([&] { YamlMap::parse("a: abc", "f.yaml").required<double>("a"); },
                      {"f.yaml: a", "a number", "abc"});
}

TEST(YamlMap, ListErrorsNameTheItemsInThePlural) {
  const YamlMap map = YamlMap::parse("w: [1, x]\nn: [1, -2]\ns: [a, [b]]\n", "l.yaml");
  try {
    map.required<std::vector<double>>("w");
    FAIL() << "no ConfigError thrown";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("expected a list of numbers, got [1, x]"),
              std::string::npos)
        << e.what();
    EXPECT_EQ(std::string(e.what()).find("a list of a "), std::string::npos) << e.what();
  }
  expect_config_error([&] { map.required<std::vector<unsigned>>("n"); },
                      {"a list of non-negative integers"});
  expect_config_error([&] { map.required<std::vector<std::string>>("s"); }, {"a list of strings"});
}

TEST(YamlMap, UnknownKeysAreErrors) {
  const YamlMap map = YamlMap::parse("radius: 1\nraduis: 2\n", "w.yaml");
  map.required<double>("radius");
  expect_config_error([&] { map.finish(); }, {"w.yaml", "raduis"});
}

TEST(YamlMap, MissingFileIsAConfigError) {
  expect_config_error([] { YamlMap::load_file("/nonexistent/x.yaml"); },
                      {"/nonexistent/x.yaml", "cannot open"});
}

// Writes `bytes` bytes of a valid YAML mapping (a key, then a comment filling the rest).
std::string write_yaml(const std::string& name, size_t bytes) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream out(path);
  const std::string head = "a: 1\n#";
  out << head << std::string(bytes - head.size(), 'x');
  return path;
}

TEST(YamlMap, FilesAreCheckedBeforeTheyAreRead) {
  // A directory (every node's file parameters end here: exit 134 before).
  expect_config_error([] { YamlMap::load_file(::testing::TempDir()); },
                      {::testing::TempDir(), "expected a YAML file, got a directory"});
  // A FIFO would block the reader forever; /dev/zero would never end.
  expect_config_error([] { YamlMap::load_file("/dev/zero"); },
                      {"/dev/zero", "expected a YAML file, got a special file"});
  // Exactly the limit is read; one byte more is refused with both numbers.
  EXPECT_EQ(YamlMap::load_file(write_yaml("limit.yaml", kMaxYamlFileBytes)).required<int>("a"), 1);
  expect_config_error([] { YamlMap::load_file(write_yaml("over.yaml", kMaxYamlFileBytes + 1)); },
                      {"over.yaml", "at most 1048576 bytes", "got 1048577 bytes"});
}

TEST(YamlMap, UnreadableFileIsAConfigError) {
  const std::string path = write_yaml("unreadable.yaml", 16);
  std::filesystem::permissions(path, std::filesystem::perms::none);
  if (std::ifstream(path).good()) {
    GTEST_SKIP() << "running as root: permissions do not stop reading";
  }
  expect_config_error([&] { YamlMap::load_file(path); },
                      {"unreadable.yaml", "cannot open the file", "Permission denied"});
}

}  // namespace
}  // namespace ari_social_sim::core
