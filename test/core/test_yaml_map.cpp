#include <gtest/gtest.h>

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

TEST(YamlMap, UnknownKeysAreErrors) {
  const YamlMap map = YamlMap::parse("radius: 1\nraduis: 2\n", "w.yaml");
  map.required<double>("radius");
  expect_config_error([&] { map.finish(); }, {"w.yaml", "raduis"});
}

TEST(YamlMap, MissingFileIsAConfigError) {
  expect_config_error([] { YamlMap::load_file("/nonexistent/x.yaml"); },
                      {"/nonexistent/x.yaml", "cannot open"});
}

}  // namespace
}  // namespace ari_social_sim::core
