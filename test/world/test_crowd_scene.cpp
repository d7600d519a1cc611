// scripts/make_crowd_scene.py: the files it writes load with the world's own loaders, hold the
// people and groups it promises, run, and come out the same for the same seed.

#include <gtest/gtest.h>
#include <stdlib.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "ari_social_sim/world/scene.hpp"

namespace ari_social_sim::world {
namespace {

const std::string kScript = std::string(ARI_SOURCE_DIR) + "/scripts/make_crowd_scene.py";

// A fresh folder under /tmp, removed with everything in it at the end of the test.
class TemporaryFolder {
 public:
  TemporaryFolder() {
    char pattern[] = "/tmp/crowd_scene_XXXXXX";
    const char* folder = mkdtemp(pattern);
    EXPECT_NE(folder, nullptr);
    path_ = folder != nullptr ? folder : "";
  }
  ~TemporaryFolder() { std::filesystem::remove_all(path_); }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

// Runs the script with `arguments`; its exit status.
int make_crowd_scene(const std::string& arguments) {
  const int status = std::system(("/usr/bin/python3 " + kScript + " " + arguments).c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string contents(const std::string& path) {
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

TEST(CrowdScene, FortyPeopleHalfInGroupsRunInsideTheHall) {
  const TemporaryFolder folder;
  const std::string& out = folder.path();
  ASSERT_EQ(make_crowd_scene("--humans 40 --seed 7 --out " + out), 0);
  const Scene scene = load_scene_file(out + "/scene.yaml");
  ASSERT_EQ(scene.humans.size(), 40u);
  size_t members = 0;
  for (const GroupSpec& group : scene.groups) {
    EXPECT_GE(group.members.size(), 2u);
    EXPECT_LE(group.members.size(), 5u);
    members += group.members.size();
  }
  EXPECT_EQ(members, 20u);
  // 4 m^2 per person plus a metre all round: a 14.65 m square hall.
  const double side = std::sqrt(40 * 4.0) + 2.0;
  auto simulation = build_simulation(scene, SimulationConfig{});
  while (simulation->time_s() < 20.0) {
    simulation->step();
  }
  for (const auto& human : simulation->humans()) {
    const Eigen::Vector2d p = human->pose().position;
    EXPECT_GT(p.minCoeff(), 0.0) << human->id();
    EXPECT_LT(p.maxCoeff(), side) << human->id();
  }
}

TEST(CrowdScene, SameSeedSameFiles) {
  const TemporaryFolder first_folder, second_folder;
  const std::string &first = first_folder.path(), &second = second_folder.path();
  ASSERT_EQ(make_crowd_scene("--humans 12 --seed 3 --out " + first), 0);
  ASSERT_EQ(make_crowd_scene("--humans 12 --seed 3 --out " + second), 0);
  EXPECT_EQ(contents(first + "/scene.yaml"), contents(second + "/scene.yaml"));
  EXPECT_EQ(contents(first + "/world.yaml"), contents(second + "/world.yaml"));
  EXPECT_FALSE(contents(first + "/scene.yaml").empty());
}

TEST(CrowdScene, TooFewPeopleOrABadSeedIsRefused) {
  const TemporaryFolder folder;
  const std::string& out = folder.path();
  EXPECT_NE(make_crowd_scene("--humans 3 --out " + out + " 2>/dev/null"), 0);
  EXPECT_NE(make_crowd_scene("--humans 10 --seed -1 --out " + out + " 2>/dev/null"), 0);
  EXPECT_TRUE(contents(out + "/scene.yaml").empty());
}

}  // namespace
}  // namespace ari_social_sim::world
