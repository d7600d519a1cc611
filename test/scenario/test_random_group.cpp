#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/scenario/random_group.hpp"

namespace ari_social_sim::scenario {
namespace {

RandomGroup spec() {
  RandomGroup group;
  group.id = 3;
  group.first_human_id = 20;
  group.min_size = 2;
  group.max_size = 5;
  group.centre_min = {2.0, 2.0};
  group.centre_max = {4.0, 3.0};
  return group;
}

TEST(RandomGroup, MembersStandEvenlyOnTheOspaceCircleFacingTheCentre) {
  core::Rng rng(5);
  const GeneratedGroup g = generate_group(spec(), rng);
  const size_t n = g.humans.size();
  ASSERT_GE(n, 2u);
  ASSERT_LE(n, 5u);
  const world::GroupSpec defaults;
  const double radius_m = world::GroupNavigation::ospace_radius_for(
      n, world::GroupNavigation::member_spacing_for(defaults, n), defaults.min_ospace_radius_m);
  for (size_t k = 0; k < n; ++k) {
    const world::HumanSpec& h = g.humans[k];
    EXPECT_EQ(h.id, 20u + k);
    EXPECT_EQ(g.group.members[k], h.id);
    EXPECT_NEAR((h.pose.position - g.group.centre).norm(), radius_m, 1e-9);
    const Eigen::Vector2d to_centre = g.group.centre - h.pose.position;
    EXPECT_NEAR(core::angle_difference(std::atan2(to_centre.y(), to_centre.x()), h.pose.theta), 0.0,
                1e-9);
    // Neighbours are 2 pi / n apart around the centre: chord 2 r sin(pi / n).
    const world::HumanSpec& next = g.humans[(k + 1) % n];
    EXPECT_NEAR((next.pose.position - h.pose.position).norm(),
                2.0 * radius_m * std::sin(core::kPi / n), 1e-9);
    EXPECT_GE(h.age_years, 18.0);
    EXPECT_LE(h.age_years, 80.0);
    EXPECT_EQ(h.age_years, std::floor(h.age_years));  // whole years
  }
  EXPECT_GE(g.group.centre.x(), 2.0);
  EXPECT_LT(g.group.centre.x(), 4.0);
  EXPECT_GE(g.group.centre.y(), 2.0);
  EXPECT_LT(g.group.centre.y(), 3.0);
}

TEST(RandomGroup, SizesCoverTheRangeUniformly) {
  core::Rng rng(11);
  std::map<size_t, int> counts;
  for (int i = 0; i < 4000; ++i) {
    ++counts[generate_group(spec(), rng).humans.size()];
  }
  ASSERT_EQ(counts.size(), 4u);  // sizes 2, 3, 4, 5 only
  for (const auto& [size, count] : counts) {
    EXPECT_NEAR(count, 1000, 100) << "size " << size;  // 4000 / 4, +-3.7 sigma
  }
}

TEST(RandomGroup, SameSeedSameGroupOtherSeedAnother) {
  core::Rng a(9), b(9), c(10);
  const GeneratedGroup ga = generate_group(spec(), a);
  const GeneratedGroup gb = generate_group(spec(), b);
  const GeneratedGroup gc = generate_group(spec(), c);
  ASSERT_EQ(ga.humans.size(), gb.humans.size());
  for (size_t k = 0; k < ga.humans.size(); ++k) {
    EXPECT_EQ(ga.humans[k].pose.position, gb.humans[k].pose.position);
    EXPECT_EQ(ga.humans[k].age_years, gb.humans[k].age_years);
  }
  EXPECT_NE(ga.group.centre, gc.group.centre);
}

}  // namespace
}  // namespace ari_social_sim::scenario
