#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include "ari_social_sim/model/world_file.hpp"
#include "expect_config_error.hpp"

namespace ari_social_sim::model {
namespace {

// Writes `text` to a file named after the test and returns its path.
std::string write_file(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

// Loading `text` fails with a message naming the file and every fragment.
void expect_rejected(const std::string& text, const std::vector<std::string>& fragments) {
  const std::string path = write_file("world_under_test.yaml", text);
  world::test::expect_config_error([&] { load_world_file(path); }, path, fragments);
}

constexpr const char* kHeader = "name: test\norigin: [0, 0]\nsize: [5, 5]\nobjects:\n";

TEST(WorldFile, ReadsEveryShapeType) {
  const std::string path =
      write_file("good_world.yaml",
                 std::string(kHeader) +
                     "  - {type: wall, from: [0, 0], to: [4, 0], thickness: 0.2}\n"
                     "  - {type: box, id: 7, name: couch, position: [2, 3], orientation: "
                     "0.5, size: [2, 0.8]}\n"
                     "  - {type: circle, position: [1, 1], radius: 0.4}\n"
                     "  - {type: polygon, points: [[3, 3], [4, 3], [4, 4]], height: 1.2}\n");
  const WorldDescription world = load_world_file(path);
  ASSERT_EQ(world.objects.size(), 4u);
  // Wall from (0,0) to (4,0): centre (2, 0), length 4, thickness 0.2.
  EXPECT_EQ(world.objects[0].type, ShapeType::kWall);
  EXPECT_DOUBLE_EQ(world.objects[0].pose.position.x(), 2.0);
  EXPECT_DOUBLE_EQ(world.objects[0].size.x(), 4.0);
  EXPECT_DOUBLE_EQ(world.objects[0].size.y(), 0.2);
  EXPECT_EQ(world.objects[1].id, 7u);
  EXPECT_EQ(world.objects[1].name, "couch");
  // Automatic ids start at 1000 and skip explicit ones.
  EXPECT_EQ(world.objects[0].id, 1000u);
  EXPECT_DOUBLE_EQ(world.objects[2].radius_m, 0.4);
  EXPECT_EQ(world.objects[3].points.size(), 3u);
  // Heights: the walls' and furniture's defaults unless given.
  EXPECT_DOUBLE_EQ(world.objects[0].height_m, kDefaultWallHeightM);
  EXPECT_DOUBLE_EQ(world.objects[1].height_m, kDefaultFurnitureHeightM);
  EXPECT_DOUBLE_EQ(world.objects[3].height_m, 1.2);
}

TEST(WorldFile, NonPositiveHeightNamesTheField) {
  expect_rejected(std::string(kHeader) +
                      "  - {type: circle, position: [1, 1], radius: 0.3, "
                      "height: 0}\n",
                  {"objects[0].height", "(0, 200]"});
}

TEST(WorldFile, UnknownTypeNamesTheEntry) {
  expect_rejected(std::string(kHeader) + "  - {type: sofa, position: [1, 1]}\n",
                  {"objects[0].type", "wall, box, circle or polygon", "sofa"});
}

TEST(WorldFile, MissingKeyAndKeyOfAnotherShapeAreNamed) {
  expect_rejected(std::string(kHeader) + "  - {type: circle, position: [1, 1]}\n",
                  {"objects[0].type", "the keys of its type", "got a circle without radius"});
  expect_rejected(std::string(kHeader) +
                      "  - {type: circle, position: [1, 1], radius: 0.5, "
                      "from: [0, 0]}\n",
                  {"objects[0].type", "got a circle with from"});
  expect_rejected(std::string(kHeader) + "  - {type: wall, from: [1, 1], to: [1, 1]}\n",
                  {"objects[0].to", "a wall needs a length"});
}

TEST(WorldFile, WrongTypeNamesFieldAndValue) {
  expect_rejected(std::string(kHeader) + "  - {type: circle, position: [1, 1], radius: big}\n",
                  {"objects[0].radius", "a number", "big"});
}

TEST(WorldFile, NegativeSizeNamesFieldAndBound) {
  expect_rejected(std::string(kHeader) + "  - {type: box, position: [1, 1], size: [1, -2]}\n",
                  {"objects[0].size", "[0.005, 200]", "-2"});
  expect_rejected("name: test\nsize: [5, -5]\nobjects: []\n", {"size", "(0, 200]"});
}

TEST(WorldFile, UnknownFieldIsNotIgnored) {
  expect_rejected(
      std::string(kHeader) + "  - {type: circle, position: [1, 1], radius: 1, colour: red}\n",
      {"objects[0]", "unknown field", "colour"});
}

TEST(WorldFile, NonConvexPolygonAndDuplicateIdsAreRejected) {
  expect_rejected(
      std::string(kHeader) + "  - {type: polygon, points: [[0,0],[2,0],[1,0.5],[2,2],[0,2]]}\n",
      {"objects[0].points", "convex"});
  expect_rejected(std::string(kHeader) +
                      "  - {type: circle, id: 3, position: [1, 1], radius: 1}\n"
                      "  - {type: circle, id: 3, position: [3, 3], radius: 1}\n",
                  {": objects", "ids used by one object each", "id 3 twice"});
}

// Each polygon here passes the old check (3-8 vertices, strictly convex or nearly so) and used to
// stop the process in a Box2D assertion (SIGABRT) when the world was built.
TEST(WorldFile, PolygonsBox2dCannotBuildAreRefusedByName) {
  const std::string polygon = std::string(kHeader) +
                              "  - {type: box, position: [1, 1], "
                              "size: [1, 1]}\n  - {type: polygon, points: ";
  expect_rejected(polygon + "[[1, 1], [1.001, 1], [1, 1.001]]}\n",
                  {"objects[1].points", "strictly convex", "got tiny: area 5e-07 m^2",
                   "expected at least 2.5e-05 m^2"});
  expect_rejected(polygon + "[[0, 0], [1, 0], [0.5, 0.0001]]}\n",
                  {"objects[1].points", "got sliver: 0.0001 m thin", "aspect 10000:1",
                   "expected at least 0.005 m"});
  expect_rejected(polygon + "[[0, 0], [1, 0], [2, 0.000001], [2, 1], [0, 1]]}\n",
                  {"objects[1].points", "got collinear: vertex 1", "expected at least 0.005 m"});
  expect_rejected(polygon + "[[0, 0], [1, 0], [1, 0], [1, 1], [0, 1]]}\n",
                  {"objects[1].points", "got duplicate vertices: 1 and 2 are 0 m apart"});
  expect_rejected(polygon + "[[0, 0], [1, 0], [1.003, 0.5], [1, 1], [0, 1]]}\n",
                  {"objects[1].points", "collinear: vertex 2 is 0.003 m off"});
}

TEST(WorldFile, ShapesThinnerThanBox2dsSlopAreRefused) {
  expect_rejected(std::string(kHeader) + "  - {type: box, position: [1, 1], size: [1, 0.001]}\n",
                  {"objects[0].size", "[0.005, 200]", "0.001"});
  expect_rejected(std::string(kHeader) + "  - {type: wall, from: [1, 1], to: [1.001, 1]}\n",
                  {"objects[0].to", "at least 0.005 m from 'from'", "got 0.001 m from 'from'"});
  expect_rejected(std::string(kHeader) + "  - {type: circle, position: [1, 1], radius: 1e-6}\n",
                  {"objects[0].radius", "[0.005, 200]", "1e-6"});
}

TEST(WorldFile, WorldsBeyondTheDocumentedMaximaAreRefused) {
  // 3000 m used to allocate a 60000 x 60000 occupancy grid and die of bad_alloc.
  expect_rejected("name: test\nsize: [3000, 10]\nobjects: []\n",
                  {": size", "each (0, 200]", "[3000, 10]"});
  expect_rejected("name: test\nsize: [10, 10]\norigin: [1e300, 0]\nobjects: []\n",
                  {": origin", "[-1000, 1000]", "1e300"});
  expect_rejected(std::string(kHeader) + "  - {type: circle, position: [1e30, 1], radius: 1}\n",
                  {"objects[0].position", "[-1000, 1000]"});
  expect_rejected(std::string(kHeader) + "  - {type: circle, position: [1, 1], radius: 1e9}\n",
                  {"objects[0].radius", "[0.005, 200]", "1e9"});
  std::string many = kHeader;
  for (int i = 0; i <= 2000; ++i) {
    many += "  - {type: circle, position: [1, 1], radius: 0.1}\n";
  }
  expect_rejected(many, {": objects", "at most 2000 objects", "2001"});
}

TEST(WorldFile, ADescriptionBuiltInCodeIsCheckedAgainstTheFilesBounds) {
  WorldDescription world;
  world.name = "built";
  world.size = {300.0, 5.0};
  world::test::expect_config_error([&] { world.validate(); }, "world 'built': size",
                                   {"each (0, 200]", "got [300, 5]"});
  world.size = {5.0, 5.0};
  world.origin = {0.0, std::nan("")};
  world::test::expect_config_error([&] { world.validate(); }, "world 'built': origin",
                                   {"[-1000, 1000]", "got [0, nan]"});
  world.origin = {0.0, 0.0};
  EXPECT_NO_THROW(world.validate());
  StaticObject shelf;
  shelf.name = "shelf";
  shelf.type = ShapeType::kPolygon;
  shelf.points = {{1.0, 1.0}, {1.001, 1.0}, {1.0, 1.001}};
  world.objects.push_back(shelf);
  world::test::expect_config_error([&] { world.validate(); }, "world 'built': objects[0] ('shelf')",
                                   {"expected a shape Box2D can build", "got tiny: area 5e-07"});
}

TEST(WorldFile, DirectoriesAndOversizedFilesAreRefusedBeforeReading) {
  world::test::expect_config_error([] { load_world_file(::testing::TempDir()); },
                                   ::testing::TempDir(), {"expected a YAML file, got a directory"});
  // 1 MiB + 1 byte of comment: refused by its size, not parsed.
  const std::string path =
      write_file("huge_world.yaml", std::string(kHeader) + "#" + std::string(1024 * 1024, 'x'));
  world::test::expect_config_error([&] { load_world_file(path); }, path,
                                   {"at most 1048576 bytes", "got 1048625 bytes"});
}

TEST(WorldFile, ShippedWorldsLoad) {
  for (const char* name : {"room_6x6", "room_12x12", "two_room_flat", "hospital_waiting_room"}) {
    const WorldDescription world =
        load_world_file(std::string(ARI_SOURCE_DIR) + "/worlds/" + name + ".yaml");
    EXPECT_EQ(world.name, name);
    EXPECT_GE(world.objects.size(), 4u);
  }
}

}  // namespace
}  // namespace ari_social_sim::model
