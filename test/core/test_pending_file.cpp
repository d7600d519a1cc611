#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/pending_file.hpp"

namespace ari_social_sim::core {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::path(::testing::TempDir()) / ("pending_file_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string read_all(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

size_t entries_in(const fs::path& dir) {
  return static_cast<size_t>(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

// A child process writes half a file and is killed with SIGKILL, which no handler can catch.
void write_half_and_die(const fs::path& path, PendingFile::Naming naming) {
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    PendingFile file(path.string(), ".active", naming);
    std::ofstream(file.writable_path()) << "half an episode";
    raise(SIGKILL);
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL);
}

TEST(PendingFile, AProcessKilledOutrightLeavesNothing) {
  const fs::path dir = scratch("killed");
  write_half_and_die(dir / "episode.bag", PendingFile::Naming::unnamed_where_possible);
  EXPECT_EQ(entries_in(dir), 0u);
}

TEST(PendingFile, WhereANameIsNeededAKilledProcessLeavesOnlyThatName) {
  const fs::path dir = scratch("killed_named");
  write_half_and_die(dir / "episode.bag", PendingFile::Naming::always_named);
  EXPECT_EQ(entries_in(dir), 1u);
  EXPECT_EQ(read_all(dir / "episode.bag.active"), "half an episode");
}

TEST(PendingFile, NamedOnlyWhenPublishedReplacingWhatWasThere) {
  for (const PendingFile::Naming naming :
       {PendingFile::Naming::unnamed_where_possible, PendingFile::Naming::always_named}) {
    const fs::path dir = scratch("publish");
    const fs::path path = dir / "episode.bag";
    std::ofstream(path) << "an earlier episode";
    {
      PendingFile file(path.string(), ".active", naming);
      EXPECT_EQ(file.named_while_written(), naming == PendingFile::Naming::always_named);
      std::ofstream(file.writable_path()) << "this episode";
      EXPECT_EQ(read_all(path), "an earlier episode");
      EXPECT_EQ(entries_in(dir), file.named_while_written() ? 2u : 1u);
      file.publish();
    }
    EXPECT_EQ(read_all(path), "this episode");
    EXPECT_EQ(entries_in(dir), 1u);
  }
}

TEST(PendingFile, DroppedUnpublishedItLeavesNothing) {
  for (const PendingFile::Naming naming :
       {PendingFile::Naming::unnamed_where_possible, PendingFile::Naming::always_named}) {
    const fs::path dir = scratch("dropped");
    {
      PendingFile file((dir / "episode.bag").string(), ".active", naming);
      std::ofstream(file.writable_path()) << "half an episode";
    }
    EXPECT_EQ(entries_in(dir), 0u);
  }
}

TEST(PendingFile, AFolderThatCannotBeWrittenIsNamed) {
  try {
    PendingFile file("/proc/no_such_folder/episode.bag", ".active");
    FAIL() << "wrote into /proc";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("/proc/no_such_folder/episode.bag: cannot write "
                                         "/proc/no_such_folder/episode.bag.active"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace ari_social_sim::core
