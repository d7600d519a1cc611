#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "../common/file_size_limit.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/output_file.hpp"

namespace ari_social_sim::core {
namespace {

namespace fs = std::filesystem;

std::string read_all(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::path(::testing::TempDir()) / ("output_file_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TEST(OutputFile, AppearsUnderItsNameOnlyWhenCommitted) {
  const fs::path dir = scratch("commit");
  const fs::path path = dir / "corpus.jsonl";
  {
    OutputFile out("--out", path.string());
    out.stream() << "line 1\n";
    EXPECT_FALSE(fs::exists(path));
    EXPECT_FALSE(fs::exists(dir / "corpus.jsonl.part"));  // unnamed while written
    out.commit();
  }
  EXPECT_EQ(read_all(path), "line 1\n");
  EXPECT_FALSE(fs::exists(dir / "corpus.jsonl.part"));
}

TEST(OutputFile, WhereTheFileSystemNeedsANameItIsThePartFile) {
  const fs::path dir = scratch("named");
  const fs::path path = dir / "corpus.jsonl";
  {
    OutputFile out("--out", path.string(), PendingFile::Naming::always_named);
    out.stream() << "line 1\n";
    EXPECT_FALSE(fs::exists(path));
    EXPECT_TRUE(fs::exists(dir / "corpus.jsonl.part"));
    out.commit();
  }
  EXPECT_EQ(read_all(path), "line 1\n");
  EXPECT_FALSE(fs::exists(dir / "corpus.jsonl.part"));
}

TEST(OutputFile, AnUncommittedFileLeavesTheEarlierOutputAlone) {
  const fs::path dir = scratch("abandon");
  const fs::path path = dir / "report.md";
  std::ofstream(path) << "earlier report\n";
  {
    OutputFile out("--report", path.string());
    out.stream() << "half a report";
  }  // e.g. an exception before commit()
  EXPECT_EQ(read_all(path), "earlier report\n");
  EXPECT_FALSE(fs::exists(dir / "report.md.part"));
}

TEST(OutputFile, FailuresNameThePath) {
  try {
    OutputFile out("--out", "/proc/ari.csv");
    FAIL() << "opened a file in /proc";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("--out: /proc/ari.csv: cannot write /proc/ari.csv.part"),
              std::string::npos)
        << e.what();
  }
}

TEST(OutputFile, AFailedWriteIsNeverCommitted) {
  for (const PendingFile::Naming naming :
       {PendingFile::Naming::unnamed_where_possible, PendingFile::Naming::always_named}) {
    const fs::path dir = scratch("full");
    OutputFile out("--csv", (dir / "out.csv").string(), naming);
    {
      const test::FileSizeLimit limit(4096);
      out.stream() << std::string(1 << 16, 'x');
      try {
        out.commit();
        FAIL() << "a failed write was committed";
      } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("out.csv: writing failed"), std::string::npos)
            << e.what();
      }
    }
    EXPECT_FALSE(fs::exists(dir / "out.csv"));
  }
}

}  // namespace
}  // namespace ari_social_sim::core
