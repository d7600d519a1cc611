#include <gtest/gtest.h>

#include <limits>

#include "ari_social_sim/world/request_check.hpp"
#include "refusal_text.hpp"
#include "scene_builders.hpp"

namespace ari_social_sim::world {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

using test::refusal_text;

TEST(RequestCheck, RefusalsNameRequestFieldExpectationAndValue) {
  const RequestCheck check("set_velocity");
  EXPECT_EQ(refusal_text([&] { check.finite("vx", kNan); }),
            "set_velocity: vx: expected a finite number, got nan");
  EXPECT_EQ(refusal_text([&] { check.finite("vx", -kInf); }),
            "set_velocity: vx: expected a finite number, got -inf");
  EXPECT_EQ(refusal_text([&] { check.finite("vx", 1e300); }), "");
  EXPECT_EQ(
      refusal_text([&] { check.in_range("omega", 1e300, core::between(-1.0, 1.0), "rad/s"); }),
      "set_velocity: omega: expected a finite number [-1, 1] rad/s, got 1e+300");
  // An open upper end still refuses infinity.
  EXPECT_EQ(refusal_text([&] { check.in_range("radius", kInf, core::positive()); }),
            "set_velocity: radius: expected a finite number > 0, got inf");
  EXPECT_EQ(refusal_text([&] { check.in_range("radius", 0.5, core::positive()); }), "");
  // Without a request name the prefix is left out (a spec's own validate()).
  EXPECT_EQ(refusal_text([] { RequestCheck().finite("age", kNan); }),
            "age: expected a finite number, got nan");
}

TEST(RequestCheck, PointsMustLieOnTheFloor) {
  // square_room(6): floor from (-0.2, -0.2), 6.4 m on each side, to (6.2, 6.2).
  const model::WorldDescription world = test::square_room(6.0);
  const RequestCheck check("set_goal");
  EXPECT_EQ(refusal_text([&] {
              check.on_floor("goal", {kNan, 1.0}, world);
            }),
            "set_goal: goal.x: expected a finite number inside the world [-0.2, 6.2], got nan");
  EXPECT_EQ(refusal_text([&] {
              check.on_floor("goal", {1.0, 6.3}, world);
            }),
            "set_goal: goal.y: expected a finite number inside the world [-0.2, 6.2], got 6.3");
  EXPECT_EQ(refusal_text([&] { check.on_floor("goal", {-0.2, 6.2}, world); }), "");  // the corners
  EXPECT_EQ(refusal_text([&] {
              check.pose_on_floor("goal", {{1.0, 1.0}, kInf}, world);
            }),
            "set_goal: goal.theta: expected a finite number [-1e+06, 1e+06] rad, got inf");
  EXPECT_EQ(refusal_text([&] { check.pose_on_floor("goal", {{1.0, 1.0}, 7.0}, world); }), "");
}

TEST(RequestCheck, ValidPrefixesASpecsRefusal) {
  HumanSpec spec;
  spec.id = 10;
  spec.age_years = kNan;
  EXPECT_EQ(refusal_text([&] { RequestCheck("spawn_human").valid(spec); }),
            "spawn_human: age: expected a number [0, 130], got nan");
}

}  // namespace
}  // namespace ari_social_sim::world
