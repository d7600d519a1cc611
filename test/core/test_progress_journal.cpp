// core::ProgressJournal: the `.active` record a batch tool resumes from.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/progress_journal.hpp"

namespace ari_social_sim::core {
namespace {

std::string read_all(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(ProgressJournal, ResumeKeepsCompleteEntriesAndCutsOffOneCutShort) {
  const std::string path = ::testing::TempDir() + "progress_journal.active";
  {
    ProgressJournal journal = ProgressJournal::start("--out", path, "settings A");
    journal.add("0", "row 0\nmore 0\n");
    journal.add("1", "row 1\n");
  }
  const std::string whole = read_all(path);
  EXPECT_EQ(whole, "settings A\nrow 0\nmore 0\ndone 0\nrow 1\ndone 1\n");
  std::ofstream(path, std::ios::app) << "row 2\ndone";  // killed while writing entry 2

  ProgressJournal resumed = ProgressJournal::resume("--out", path, "settings A");
  ASSERT_EQ(resumed.kept().size(), 2u);
  EXPECT_EQ(resumed.kept()[0].key, "0");
  EXPECT_EQ(resumed.kept()[0].lines, "row 0\nmore 0\n");
  EXPECT_EQ(resumed.kept()[1].key, "1");
  EXPECT_EQ(resumed.kept()[1].lines, "row 1\n");
  EXPECT_TRUE(resumed.was_cut_short());
  EXPECT_EQ(read_all(path), whole);
  resumed.add("2", "row 2\n");
  EXPECT_EQ(read_all(path), whole + "row 2\ndone 2\n");
  resumed.remove();
  EXPECT_FALSE(std::filesystem::exists(path));
}

TEST(ProgressJournal, OtherSettingsAreRefusedShowingBoth) {
  const std::string path = ::testing::TempDir() + "progress_journal_other.active";
  ProgressJournal::start("--csv", path, "episodes=2 seed=1").add("0", "row\n");
  try {
    ProgressJournal::resume("--csv", path, "episodes=3 seed=1");
    FAIL() << "resumed with other settings";
  } catch (const ConfigError& e) {
    EXPECT_STREQ(e.what(), ("--csv: " + path +
                            " was made with other settings:\n  there: episodes=2 seed=1\n  now:   "
                            "episodes=3 seed=1\npass the same options, or --overwrite to start "
                            "again")
                               .c_str());
  }
  EXPECT_THROW(ProgressJournal::start("--csv", path, "s").add("0", "done early\n"),
               std::logic_error);
}

}  // namespace
}  // namespace ari_social_sim::core
