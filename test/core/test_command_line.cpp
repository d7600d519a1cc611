#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <vector>

#include "ari_social_sim/core/command_line.hpp"
#include "ari_social_sim/core/error.hpp"

namespace ari_social_sim::core {
namespace {

namespace fs = std::filesystem;

// The message of the ConfigError `body` throws; fails the test when it throws none.
template <class F>
std::string config_error(F body) {
  try {
    body();
  } catch (const ConfigError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no ConfigError thrown";
  return "";
}

// A fresh empty directory for one test.
fs::path scratch(const std::string& name) {
  const fs::path dir = fs::path(::testing::TempDir()) / ("command_line_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

constexpr IntegerOption kCount{"--count", 1, 100000};

TEST(IntegerOption, ReadsIntegersWithinTheRange) {
  EXPECT_EQ(kCount.parse("1"), 1);
  EXPECT_EQ(kCount.parse("100000"), 100000);
  EXPECT_EQ(kCount.range(), "[1, 100000]");
  constexpr IntegerOption kOffset{"--offset", -5, 5};
  EXPECT_EQ(kOffset.parse("-5"), -5);
  EXPECT_EQ(kOffset.parse("-0"), 0);
}

TEST(IntegerOption, RefusesWhatWouldWrapTruncateOrFallOutside) {
  // -1 read as unsigned would be 2^64 - 1 (the report: a corpus of 2^64 dialogues).
  EXPECT_EQ(config_error([] { kCount.parse("-1"); }),
            "--count: expected an integer in [1, 100000], got '-1'");
  for (const char* bad : {"0", "100001", "", "-", "+3", " 3", "3 ", "3x", "0x10", "1e3", "2.5",
                          "99999999999999999999", "-99999999999999999999"}) {
    const std::string message = config_error([&] { kCount.parse(bad); });
    EXPECT_NE(
        message.find("--count: expected an integer in [1, 100000], got '" + std::string(bad) + "'"),
        std::string::npos)
        << message;
  }
  constexpr IntegerOption kWide{"--seed", 0, std::numeric_limits<int64_t>::max()};
  EXPECT_EQ(kWide.parse("9223372036854775807"), std::numeric_limits<int64_t>::max());
  // 2^63 is one beyond int64: refused, not wrapped to a negative seed.
  EXPECT_FALSE(config_error([&] { kWide.parse("9223372036854775808"); }).empty());
}

TEST(NumberOption, ReadsFiniteNumbersWithinTheBounds) {
  const NumberOption stride{"--stride", positive()};
  EXPECT_DOUBLE_EQ(stride.parse("0.5"), 0.5);
  EXPECT_DOUBLE_EQ(stride.parse("5e1"), 50.0);
  for (const char* bad : {"0", "-1", "nan", "inf", "1e400", "", " 1", "1m", "0x"}) {
    EXPECT_NE(config_error([&] {
                stride.parse(bad);
              }).find("--stride: expected a finite number > 0, got '" + std::string(bad) + "'"),
              std::string::npos)
        << bad;
  }
  const NumberOption weight{"--prior-weight", between(0.0, 1e6)};
  EXPECT_DOUBLE_EQ(weight.parse("0"), 0.0);
  EXPECT_NE(config_error([&] { weight.parse("2e6"); }).find("[0, 1e+06]"), std::string::npos);
}

TEST(OptionValue, TakesTheNextArgumentUnlessMissingOrEmpty) {
  std::vector<std::string> words = {"tool", "--out", "x.csv", "--seed", "", "--report"};
  std::vector<char*> argv;
  for (std::string& word : words) {
    argv.push_back(word.data());
  }
  const int argc = static_cast<int>(argv.size());
  int i = 1;
  EXPECT_EQ(option_value(argc, argv.data(), i), "x.csv");
  EXPECT_EQ(i, 2);  // on the value: the caller's loop steps past it
  i = 3;
  EXPECT_EQ(config_error([&] { option_value(argc, argv.data(), i); }),
            "--seed: expected a value, got ''");
  i = 5;
  EXPECT_EQ(config_error([&] { option_value(argc, argv.data(), i); }),
            "--report: expected a value after it");
}

TEST(CheckKnownOption, CallsAnUnknownOptionUnknownEvenWhenLast) {
  EXPECT_NO_THROW(check_known_option("--out", {"--seed", "--out"}));
  // `tool --seed 1 --frobnicate`: unknown, not a known option missing its value.
  EXPECT_EQ(config_error([] {
              check_known_option("--frobnicate", {"--seed", "--out"});
            }),
            "--frobnicate: unknown option, expected one of --seed, --out");
}

TEST(CheckInputFile, RefusesDirectoriesAndMissingFiles) {
  const fs::path dir = scratch("input");
  const fs::path file = dir / "in.yaml";
  std::ofstream(file) << "a: 1\n";
  EXPECT_NO_THROW(check_input_file("--config", file.string()));
  EXPECT_EQ(config_error([&] { check_input_file("--config", dir.string()); }),
            "--config: " + dir.string() + ": expected a readable file, got a directory");
  EXPECT_NE(config_error([&] {
              check_input_file("--config", (dir / "none").string());
            }).find("none: cannot open the file (No such file or directory)"),
            std::string::npos);
  // A loop is no missing file: say what it is.
  const fs::path loop = dir / "loop.yaml";
  fs::create_symlink(loop, loop);
  EXPECT_EQ(config_error([&] { check_input_file("--config", loop.string()); }),
            "--config: " + loop.string() + ": cannot open the file (a symbolic link loop)");
  EXPECT_EQ(config_error([&] { check_output_file("--out", loop.string(), true); }),
            "--out: " + loop.string() + ": expected a file name, got a symbolic link loop");
  EXPECT_NO_THROW(check_input_directory("--corpus", dir.string()));
  EXPECT_NE(config_error([&] {
              check_input_directory("--corpus", file.string());
            }).find("expected a directory, got a file"),
            std::string::npos);
  EXPECT_NE(config_error([&] {
              check_input_directory("--corpus", (dir / "none").string());
            }).find("got nothing (no such path)"),
            std::string::npos);
}

TEST(CheckOutputFile, RefusesExistingDirectoriesAndUnwritableFolders) {
  const fs::path dir = scratch("output");
  const fs::path file = dir / "out.jsonl";
  EXPECT_NO_THROW(check_output_file("--out", file.string(), false));
  EXPECT_FALSE(fs::exists(file));  // checking writes nothing under the name
  EXPECT_EQ(fs::directory_iterator(dir), fs::directory_iterator());  // nor the probe
  std::ofstream(file) << "earlier run\n";
  EXPECT_EQ(config_error([&] { check_output_file("--out", file.string(), false); }),
            "--out: " + file.string() + ": exists (pass --overwrite to replace it)");
  EXPECT_NO_THROW(check_output_file("--out", file.string(), true));
  EXPECT_EQ(config_error([&] { check_output_file("--out", dir.string(), true); }),
            "--out: " + dir.string() + ": expected a file name, got a directory");
  EXPECT_NE(config_error([&] {
              check_output_file("--out", (dir / "no/x.md").string(), false);
            }).find("does not exist"),
            std::string::npos);
  // A file standing where a folder should be.
  EXPECT_NE(config_error([&] {
              check_output_file("--out", (file / "x.md").string(), false);
            }).find("does not exist"),
            std::string::npos);
  // /proc takes no new files, even from root, whom permission bits never stop.
  EXPECT_NE(config_error([] {
              check_output_file("--report", "/proc/report.md", false);
            }).find("--report: /proc/report.md: cannot write in /proc"),
            std::string::npos);
}

TEST(PrepareOutputDirectory, CreatesMissingFoldersAndRefusesFiles) {
  const fs::path dir = scratch("prepare");
  EXPECT_NO_THROW(prepare_output_directory("--out", (dir / "a/b").string()));
  EXPECT_TRUE(fs::is_directory(dir / "a/b"));
  EXPECT_EQ(fs::directory_iterator(dir / "a/b"), fs::directory_iterator());
  std::ofstream(dir / "file") << "x";
  EXPECT_EQ(config_error([&] { prepare_output_directory("--out", (dir / "file").string()); }),
            "--out: " + (dir / "file").string() + ": expected a directory, got a file");
  EXPECT_NE(config_error([&] {
              prepare_output_directory("--out", (dir / "file/sub").string());
            }).find("cannot create the directory"),
            std::string::npos);
  EXPECT_NE(config_error([] {
              prepare_output_directory("--out", "/proc/ari_out");
            }).find("--out: /proc/ari_out: cannot create the directory"),
            std::string::npos);
  EXPECT_NE(config_error([] {
              prepare_output_directory("--out", "/proc");
            }).find("--out: /proc: cannot write in the directory"),
            std::string::npos);
}

}  // namespace
}  // namespace ari_social_sim::core
