#include <gtest/gtest.h>

#include "ari_social_sim/navigation/episode_scorer.hpp"
#include "navigation_fixtures.hpp"

namespace ari_social_sim::navigation {
namespace {

const FootprintModel kFootprint = FootprintModel::covering(model::AriFootprint{}, 3);

// ARI driving along y = 0 from x = 0 at 1 m/s, ticks of 0.1 s, past `people`.
EpisodeScore drive_past(const std::vector<PersonEstimate>& people,
                        const std::vector<GroupEstimate>& groups, const std::string& exempt_group,
                        const std::vector<std::string>& exempt_people, int ticks) {
  EpisodeScorer scorer(kFootprint, PersonalSpaceParams{}, exempt_people, exempt_group);
  for (int i = 0; i <= ticks; ++i) {
    ScoredTick tick;
    tick.time_s = 0.1 * i;
    tick.ari = test::pose(0.1 * i, 0.0, 0.0);
    tick.linear_mps = 1.0;
    tick.people = people;
    tick.groups = groups;
    scorer.add(tick);
  }
  return scorer.score();
}

TEST(EpisodeScorer, PathDistanceAndPersonalSpaceShare) {
  // A person facing the path 1.0 m to its side at x = 5: ARI's side (y = 0.27) comes within
  // 0.73 m of their centre, 0.53 m of their body. Their 2-sigma edge (1.2 m ahead, 0.8 m aside)
  // crosses y = 0.27 at x = 5 +- 0.8 sqrt(1 - (0.73 / 1.2)^2) = 5 +- 0.635; the footprint spans
  // x - 0.60 .. x + 0.16, so ARI is inside for base x in [4.2, 6.2]: 2.0 m of the 10 m.
  const std::vector<PersonEstimate> people = {test::person("p", 5.0, 1.0, -M_PI / 2)};
  const EpisodeScore score = drive_past(people, {}, "", {}, 100);
  EXPECT_NEAR(score.path_length_m, 10.0, 1e-9);
  EXPECT_NEAR(score.duration_s, 10.0, 1e-9);
  EXPECT_NEAR(score.min_person_distance_m, 1.0 - 0.27 - 0.2, 1e-9);
  EXPECT_NEAR(score.personal_space_share, 0.2, 0.015);
  EXPECT_EQ(score.person_collisions, 0);
  EXPECT_DOUBLE_EQ(score.mean_abs_jerk, 0.0);  // constant speed
  // The same person approached on purpose does not count.
  EXPECT_DOUBLE_EQ(drive_past(people, {}, "", {"p"}, 100).personal_space_share, 0.0);
}

TEST(EpisodeScorer, CollisionsAndOspaceIntrusionsCountEntries) {
  // A person on the path: one contact (entering it once), however long it lasts.
  const EpisodeScore hit = drive_past({test::person("p", 5.0, 0.1, 0.0)}, {}, "", {}, 100);
  EXPECT_EQ(hit.person_collisions, 1);
  EXPECT_LT(hit.min_person_distance_m, 0.0);
  // A group whose o-space straddles the path: one intrusion, none when it is the group joined.
  GroupEstimate group;
  group.id = "g";
  group.centre = {5.0, 0.5};
  group.radius_m = 0.8;  // o-space disc 0.6 m: ARI's side at y = 0.27 reaches into it
  EXPECT_EQ(drive_past({}, {group}, "", {}, 100).ospace_intrusions, 1);
  EXPECT_EQ(drive_past({}, {group}, "g", {}, 100).ospace_intrusions, 0);
}

}  // namespace
}  // namespace ari_social_sim::navigation
