#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "../common/data_sets.hpp"
#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/perception/fformation_dataset.hpp"

namespace ari_social_sim::perception {
namespace {

// Writes `text` to a fresh file in the test's temporary directory and returns its path.
std::string write_file(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + "fformation_" + name;
  std::ofstream(path) << text;
  return path;
}

// Expects `body` to throw ConfigError whose message contains every fragment.
template <class F>
void expect_config_error(F body, const std::vector<std::string>& fragments) {
  try {
    body();
    FAIL() << "no ConfigError thrown";
  } catch (const core::ConfigError& e) {
    for (const std::string& fragment : fragments) {
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos)
          << "'" << fragment << "' missing from: " << e.what();
    }
  }
}

TEST(FformationDataset, ReadsFeaturesPerFrameInFileOrder) {
  const std::string path = write_file("features.csv",
                                      "frame,person_id,x,y,theta\r\n"
                                      "3,7,1.5,-2,3.141593\r\n"
                                      "\r\n"
                                      "1, bob ,0,0,0\n"
                                      "3,alice,10,20,-1.5\n");
  const FeatureTable table = read_fformation_features(path);
  ASSERT_EQ(table.size(), 2u);
  ASSERT_EQ(table.at(3).size(), 2u);
  EXPECT_EQ(table.at(3)[0].id, "7");
  EXPECT_DOUBLE_EQ(table.at(3)[0].x, 1.5);
  EXPECT_DOUBLE_EQ(table.at(3)[0].y, -2.0);
  EXPECT_DOUBLE_EQ(table.at(3)[0].theta, 3.141593);
  EXPECT_EQ(table.at(3)[1].id, "alice");
  EXPECT_EQ(table.at(1)[0].id, "bob");
}

TEST(FformationDataset, ReadsGroupsInOrderOfFirstAppearance) {
  const std::string path = write_file("groups.csv",
                                      "frame,group,person_id\n"
                                      "1,5,a\n"
                                      "1,2,b\n"
                                      "1,5,c\n"
                                      "2,5,d\n"
                                      "2,5,e\n");
  const GroupTable table = read_fformation_groups(path);
  EXPECT_EQ(table.at(1), (Grouping{{"a", "c"}, {"b"}}));
  EXPECT_EQ(table.at(2), (Grouping{{"d", "e"}}));
}

TEST(FformationDataset, ReadsFramesInFileOrder) {
  const std::string path = write_file("frames.csv", "frame\n4\n1\n-2\n");
  EXPECT_EQ(read_fformation_frames(path), (std::vector<FrameId>{4, 1, -2}));
}

TEST(FformationDataset, ReadsTheSharedSynthSet) {
  ARI_SKIP_WITHOUT_DATA_SET("fformation");
  const std::string base = core::data_set_dir("fformation") + "/Synth_";
  const FeatureTable features = read_fformation_features(base + "features.csv");
  const std::vector<FrameId> frames = read_fformation_frames(base + "frames.csv");
  EXPECT_EQ(frames.size(), 100u);
  // First row: "1,1,260.0000,200.0000,0.000000"; second "1,2,280,240,4.712389" (3 pi / 2).
  ASSERT_FALSE(features.at(1).empty());
  EXPECT_EQ(features.at(1)[0].id, "1");
  EXPECT_DOUBLE_EQ(features.at(1)[0].x, 260.0);
  EXPECT_NEAR(features.at(1)[1].theta, 1.5 * core::kPi, 1e-6);
  EXPECT_EQ(read_fformation_groups(base + "groups.csv").at(1)[0],
            (std::vector<std::string>{"1", "2"}));
}

TEST(FformationDataset, ErrorsNameFileLineColumnAndField) {
  const std::string header = "frame,person_id,x,y,theta\n";
  // "1,2,abc": x starts at character 5 of line 3.
  const std::string bad_number = write_file("bad_number.csv", header + "1,1,0,0,0\n1,2,abc,0,0\n");
  expect_config_error([&] { read_fformation_features(bad_number); },
                      {bad_number + ":3:5:", "x:", "finite number", "\"abc\""});
  const std::string bad_frame = write_file("bad_frame.csv", header + "1.5,1,0,0,0\n");
  expect_config_error([&] { read_fformation_features(bad_frame); },
                      {bad_frame + ":2:1:", "frame:", "integer", "\"1.5\""});
  const std::string empty_id = write_file("empty_id.csv", header + "1,,0,0,0\n");
  expect_config_error([&] { read_fformation_features(empty_id); },
                      {empty_id + ":2:3:", "person_id:", "non-empty"});
  const std::string infinite = write_file("infinite.csv", header + "1,1,0,inf,0\n");
  expect_config_error([&] { read_fformation_features(infinite); }, {":2:7:", "y:", "\"inf\""});
}

TEST(FformationDataset, TablesAreCheckedBeforeTheyAreRead) {
  expect_config_error([] { read_fformation_features(::testing::TempDir()); },
                      {::testing::TempDir(), "expected a CSV file, got a directory"});
  expect_config_error([] { read_fformation_groups("/dev/zero"); },
                      {"/dev/zero", "expected a CSV file, got a special file"});
}

TEST(FformationDataset, WrongShapesAreErrors) {
  const std::string header = "frame,person_id,x,y,theta\n";
  const std::string few = write_file("few.csv", header + "1,1,0,0\n");
  expect_config_error([&] { read_fformation_features(few); },
                      {few + ":2:8:", "expected 5 fields", "got 4"});
  const std::string many = write_file("many.csv", header + "1,1,0,0,0,9\n");
  expect_config_error([&] { read_fformation_features(many); },
                      {many + ":2:11:", "expected 5 fields", "got 6"});
  const std::string wrong_header = write_file("wrong_header.csv", "frame,id,x,y,theta\n");
  expect_config_error([&] { read_fformation_features(wrong_header); },
                      {wrong_header + ":1:1:", "frame,person_id,x,y,theta", "frame,id,x,y,theta"});
  const std::string empty = write_file("empty.csv", "");
  expect_config_error([&] { read_fformation_groups(empty); },
                      {empty + ":1:1:", "frame,group,person_id", "empty file"});
  expect_config_error([] { read_fformation_frames("/nonexistent/frames.csv"); },
                      {"/nonexistent/frames.csv", "cannot open"});
}

TEST(FformationDataset, RepeatsAreErrors) {
  const std::string person = write_file("twice.csv",
                                        "frame,person_id,x,y,theta\n1,a,0,0,0\n"
                                        "2,a,0,0,0\n1,a,1,1,1\n");
  expect_config_error([&] { read_fformation_features(person); },
                      {person + ":4:3:", "\"a\" appears twice in frame 1"});
  const std::string member = write_file("member.csv", "frame,group,person_id\n1,0,a\n1,1,a\n");
  expect_config_error([&] { read_fformation_groups(member); },
                      {member + ":3:5:", "\"a\" is in two groups of frame 1"});
  const std::string frame = write_file("frame.csv", "frame\n1\n2\n1\n");
  expect_config_error([&] { read_fformation_frames(frame); },
                      {frame + ":4:1:", "frame 1 is listed twice"});
}

TEST(FformationDataset, DetectsGroupsInEveryFrame) {
  // Frame 1: a face-to-face pair 120 cm apart; frame 2: a lone person, still listed.
  const std::string path = write_file("detect.csv",
                                      "frame,person_id,x,y,theta\n"
                                      "1,a,0,0,0\n1,b,120,0,3.141593\n2,c,0,0,0\n");
  GcffParams params;
  params.stride = 60.0;
  params.mdl = 8000.0;
  const GroupTable groups = detect_fformation_groups(read_fformation_features(path), params);
  EXPECT_EQ(groups.at(1), (Grouping{{"a", "b"}}));
  EXPECT_TRUE(groups.at(2).empty());
}

TEST(FformationDataset, StopsBeforeTheFrameItIsToldTo) {
  const std::string path = write_file("stop.csv",
                                      "frame,person_id,x,y,theta\n"
                                      "1,a,0,0,0\n1,b,120,0,3.141593\n2,c,0,0,0\n3,d,0,0,0\n");
  GcffParams params;
  params.stride = 60.0;
  params.mdl = 8000.0;
  // Asked before each frame, as detect_groups asks whether a stop signal came: yes at the second.
  int asked = 0;
  const GroupTable groups = detect_fformation_groups(read_fformation_features(path), params,
                                                     [&asked] { return ++asked == 2; });
  EXPECT_EQ(asked, 2);
  ASSERT_EQ(groups.size(), 1u);
  EXPECT_EQ(groups.at(1), (Grouping{{"a", "b"}}));
}

}  // namespace
}  // namespace ari_social_sim::perception
