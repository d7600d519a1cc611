// Files a user names are checked on the file system before a byte is read, and read no further
// than their limit.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/text_file.hpp"

namespace ari_social_sim::core {
namespace {

std::string write_file(const std::string& name, size_t bytes) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << std::string(bytes, 'x');
  return path;
}

std::string error_of(const std::function<void()>& call) {
  try {
    call();
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "no error";
}

TEST(TextFile, NamesWhatWasExpectedAndWhatWasFound) {
  EXPECT_EQ(error_of([] { read_text_file("/nonexistent/robot.urdf", "a URDF file", 10); }),
            "/nonexistent/robot.urdf: cannot open the file (it does not exist)");
  EXPECT_EQ(error_of([] { read_text_file("/tmp", "a URDF file", 10); }),
            "/tmp: expected a URDF file, got a directory");
  EXPECT_EQ(error_of([] { check_text_file("/dev/null", "a CSV file", 10); }),
            "/dev/null: expected a CSV file, got a special file (device, FIFO or socket)");
}

TEST(TextFile, ASymbolicLinkLoopIsCalledSoNotMissing) {
  const std::string loop = ::testing::TempDir() + "text_file_loop.yaml";
  std::filesystem::remove(loop);
  std::filesystem::create_symlink(loop, loop);
  EXPECT_EQ(error_of([&] { check_text_file(loop, "a YAML file", 100); }),
            loop + ": cannot open the file (a symbolic link loop)");
  EXPECT_EQ(error_of([&] { check_text_file(loop + "_none", "a YAML file", 100); }),
            loop + "_none: cannot open the file (it does not exist)");
}

TEST(TextFile, ReadsUpToTheLimitAndRefusesAByteMore) {
  EXPECT_EQ(read_text_file(write_file("ten.txt", 10), "a text", 10), std::string(10, 'x'));
  EXPECT_EQ(check_text_file(write_file("ten.txt", 10), "a text", 10), 10u);
  const std::string eleven = write_file("eleven.txt", 11);
  EXPECT_EQ(error_of([&] { read_text_file(eleven, "a text", 10); }),
            eleven + ": expected a text of at most 10 bytes, got 11 bytes");
}

}  // namespace
}  // namespace ari_social_sim::core
