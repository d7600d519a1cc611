// Runs the render_cameras program as a user would: the world and every picture's place checked
// before the renderer starts.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "program_run.hpp"

namespace ari_social_sim::tools::test {
namespace {

namespace fs = std::filesystem;

ProgramRun run(const std::string& arguments) {
  return run_program(ARI_RENDER_CAMERAS_BIN, arguments);
}

const std::string kWorld = std::string(ARI_SOURCE_DIR) + "/worlds/hospital_waiting_room.yaml";

TEST(RenderCameras, BadOptionsExitWithTwoBeforeRendering) {
  const std::string dir = ::testing::TempDir() + "render_cameras_bad";
  fs::remove_all(dir);
  for (const auto& [arguments, fragment] : std::vector<std::pair<std::string, std::string>>{
           {"--world " + ::testing::TempDir() + " --out " + dir,
            "--world: " + ::testing::TempDir() + ": expected a readable file, got a directory"},
           {"--world /nonexistent.yaml --out " + dir, "/nonexistent.yaml: cannot open"},
           {"--world " + kWorld + " --out /etc/hostname",
            "--out: /etc/hostname: expected a directory, got a file"},
           {"--world " + kWorld + " --out /proc/pictures", "cannot create the directory"},
           {"--world " + kWorld, "--world and --out are required"},
           {"--world " + kWorld + " --out ''", "--out: expected a value, got ''"},
           {"--world " + kWorld + " --out " + dir + " --zoom 2", "'--zoom'"}}) {
    const ProgramRun result = run(arguments);
    expect_refused(result, fragment);
    EXPECT_EQ(result.out.find("renderer:"), std::string::npos) << arguments;
  }
  EXPECT_FALSE(fs::exists(dir));
}

TEST(RenderCameras, PicturesThereAreKeptWithoutOverwrite) {
  const std::string dir = ::testing::TempDir() + "render_cameras_existing";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir + "/camera_head.png") << "a picture from last week";
  const ProgramRun result = run("--world " + kWorld + " --out " + dir);
  expect_refused(result, dir + "/camera_head.png: exists (pass --overwrite to replace it)");
  EXPECT_EQ(result.out.find("renderer:"), std::string::npos);
  EXPECT_EQ(read_all(dir + "/camera_head.png"), "a picture from last week");
}

}  // namespace
}  // namespace ari_social_sim::tools::test
