// The config idiom (config_fields.hpp) on a small config: one visit read from YAML, checked in
// code, written back and documented.

#include <gtest/gtest.h>

#include "ari_social_sim/core/config_check.hpp"
#include "ari_social_sim/core/config_reader.hpp"
#include "ari_social_sim/core/config_writer.hpp"
#include "ari_social_sim/core/parameter_table.hpp"

namespace ari_social_sim::core {
namespace {

enum class Flavour { kPlain, kSalted };
constexpr Choice<Flavour> kFlavours[] = {{Flavour::kPlain, "plain"}, {Flavour::kSalted, "salted"}};

struct Oven {
  double temperature_c{180.0};
  int minutes{20};

  template <class V>
  void visit(V& v) {
    v.field("temperature", temperature_c, "degrees Celsius", between(50.0, 300.0));
    v.field("minutes", minutes, "baking time", positive());
  }
};

struct Recipe {
  std::string name;
  unsigned servings{4};
  int64_t seed{-1};
  std::vector<double> shares{0.5, 0.5};
  std::optional<double> salt_g;
  Flavour flavour{Flavour::kPlain};
  Oven oven;

  template <class V>
  void visit(V& v) {
    v.field(required("name"), name, "what it is called");
    v.field("servings", servings, "people fed", between(1.0, 12.0));
    v.field("seed", seed, "random stream; -1 = none", Bounds{-1.0, 1000.0, false});
    v.field("shares", shares, "flour and water", between(0.0, 1.0));
    v.field("salt_g", salt_g, "grams of salt; unset: none", non_negative());
    v.choice("flavour", flavour, "how it tastes", kFlavours);
    v.rule("salt_g", flavour == Flavour::kSalted || !salt_g, "no salt unless salted",
           salt_g ? number_text(*salt_g) : "");
    v.section("oven", oven, "how it is baked");
  }
};

Recipe read(const std::string& text) {
  return read_fields<Recipe>(YamlMap::parse(text, "r.yaml"));
}

std::string read_error(const std::string& text) {
  try {
    read(text);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "accepted";
}

std::string check_error(const Recipe& recipe) {
  try {
    check_fields(recipe, "Recipe");
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(ConfigFields, ReadsPresentKeysOverTheDefaults) {
  const Recipe recipe = read(
      "{name: bread, seed: 7, shares: [0.6, 0.4], salt_g: 9, flavour: salted, oven: {minutes: "
      "35}}");
  EXPECT_EQ(recipe.name, "bread");
  EXPECT_EQ(recipe.servings, 4u);
  EXPECT_EQ(recipe.seed, 7);
  EXPECT_EQ(recipe.shares, (std::vector<double>{0.6, 0.4}));
  EXPECT_EQ(recipe.salt_g, std::optional<double>(9.0));
  EXPECT_EQ(recipe.flavour, Flavour::kSalted);
  EXPECT_DOUBLE_EQ(recipe.oven.temperature_c, 180.0);
  EXPECT_EQ(recipe.oven.minutes, 35);
  EXPECT_FALSE(read("{name: bread}").salt_g.has_value());
}

TEST(ConfigFields, ReadingNamesTheFileTheFieldAndTheExpectation) {
  EXPECT_EQ(read_error("{servings: 2}"),
            "r.yaml: name: expected a value (the field is required), got nothing");
  EXPECT_EQ(read_error("{name: a, servings: 13}"),
            "r.yaml: servings: expected a non-negative integer [1, 12], got 13");
  EXPECT_EQ(read_error("{name: a, flavour: sweet}"),
            "r.yaml: flavour: expected plain or salted, got 'sweet'");
  EXPECT_EQ(read_error("{name: a, salt_g: 3}"),
            "r.yaml: salt_g: expected no salt unless salted, got 3");
  EXPECT_EQ(read_error("{name: a, oven: {temperature: 400}}"),
            "r.yaml: oven.temperature: expected a number [50, 300], got 400");
  EXPECT_EQ(read_error("{name: a, oven: {heat: 1}}"),
            "r.yaml: oven: unknown field(s) heat (check the spelling)");
  EXPECT_EQ(read_error("{name: a, sugar: 1}"),
            "r.yaml: top level: unknown field(s) sugar (check the spelling)");
}

TEST(ConfigFields, CheckingACodeBuiltConfigNamesTheStructAndTheField) {
  Recipe recipe;
  recipe.name = "bread";
  EXPECT_EQ(check_error(recipe), "accepted");
  recipe.oven.temperature_c = std::nan("");
  EXPECT_EQ(check_error(recipe), "Recipe: oven.temperature: expected a number [50, 300], got nan");
  recipe.oven.temperature_c = 1e300 * 1e300;
  EXPECT_EQ(check_error(recipe), "Recipe: oven.temperature: expected a number [50, 300], got inf");
  recipe.oven = Oven{};
  recipe.shares = {0.5, 1.5};
  EXPECT_EQ(check_error(recipe),
            "Recipe: shares: expected a list of numbers, each [0, 1], got [0.5, 1.5]");
  recipe.shares = {};
  recipe.flavour = static_cast<Flavour>(5);
  EXPECT_EQ(check_error(recipe), "Recipe: flavour: expected plain or salted, got the value 5");
  recipe.flavour = Flavour::kPlain;
  recipe.salt_g = -1.0;
  EXPECT_EQ(check_error(recipe), "Recipe: salt_g: expected a number >= 0, got -1");
  recipe.salt_g.reset();
  recipe.name.clear();
  EXPECT_EQ(check_error(recipe), "Recipe: name: expected a value (the field is required), got ''");
}

TEST(ConfigFields, WithoutAnOwnerTheMessageStartsAtTheField) {
  Recipe recipe;
  recipe.name = "bread";
  recipe.oven.minutes = 0;
  try {
    check_fields(recipe, "");
    FAIL() << "accepted";
  } catch (const ConfigError& e) {
    EXPECT_STREQ(e.what(), "oven.minutes: expected an integer > 0, got 0");
  }
}

TEST(ConfigFields, WrittenYamlReadsBackToTheSameValues) {
  Recipe recipe;
  recipe.name = "bread";
  recipe.oven.temperature_c = 500.0 / 3.0;
  recipe.salt_g = 2.5;
  recipe.flavour = Flavour::kSalted;
  const Recipe back = read(write_fields(recipe));
  EXPECT_EQ(back.oven.temperature_c, recipe.oven.temperature_c);
  EXPECT_EQ(back.salt_g, recipe.salt_g);
  EXPECT_EQ(back.flavour, Flavour::kSalted);
  EXPECT_EQ(write_fields(back), write_fields(recipe));
}

TEST(ConfigFields, TheTableListsEveryFieldWithItsDefaultAndRange) {
  const ParameterTable table = parameter_table<Recipe>();
  ASSERT_EQ(table.rows().size(), 9u);
  const ParameterRow& servings = table.rows()[1];
  EXPECT_EQ(servings.path, (std::vector<std::string>{"servings"}));
  EXPECT_EQ(servings.type, "non-negative integer");
  EXPECT_EQ(servings.default_value, "`4`");
  EXPECT_EQ(servings.range, "[1, 12]");
  EXPECT_EQ(table.rows()[0].default_value, "required");
  EXPECT_EQ(table.rows()[3].range, "each [0, 1]");
  EXPECT_EQ(table.rows()[4].default_value, "unset");
  EXPECT_EQ(table.rows()[5].range, "plain or salted");
  EXPECT_EQ(table.rows()[8].path, (std::vector<std::string>{"oven", "minutes"}));
  const std::string markdown = table.markdown("~", "/");
  EXPECT_NE(markdown.find("| `~oven/temperature` | number | `180` | [50, 300] | degrees Celsius |"),
            std::string::npos)
      << markdown;
  EXPECT_NE(markdown.find("- `~salt_g`: no salt unless salted"), std::string::npos) << markdown;
}

}  // namespace
}  // namespace ari_social_sim::core
