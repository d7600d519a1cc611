#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/world/scene.hpp"
#include "ari_social_sim/world/simulation.hpp"
#include "scene_builders.hpp"

namespace ari_social_sim::world {
namespace {

constexpr double kSideM = 10.0;
const Eigen::Vector2d kCentre{5.0, 5.0};

// A 10 x 10 m room with a group of `size` round (5, 5), ids 10, 11, ..., and humans standing
// alone at `passers_by` (ids 20, 21, ...).
std::unique_ptr<Simulation> turnover_world(uint64_t seed, int size,
                                           const GroupTurnoverSpec& turnover,
                                           const std::vector<Eigen::Vector2d>& passers_by = {}) {
  SimulationConfig config;
  config.seed = seed;
  auto simulation = std::make_unique<Simulation>(test::square_room(kSideM), config);
  GroupSpec group;
  group.id = 1;
  group.centre = kCentre;
  group.turnover = turnover;
  for (int k = 0; k < size; ++k) {
    HumanSpec spec;
    spec.id = static_cast<model::ObjectId>(10 + k);
    const double bearing = 2.0 * M_PI * k / size;
    spec.pose = {kCentre + 0.7 * Eigen::Vector2d(std::cos(bearing), std::sin(bearing)),
                 bearing + M_PI};
    simulation->add_human(spec);
    group.members.push_back(spec.id);
  }
  for (size_t k = 0; k < passers_by.size(); ++k) {
    HumanSpec spec;
    spec.id = static_cast<model::ObjectId>(20 + k);
    spec.pose.position = passers_by[k];
    simulation->add_human(spec);
  }
  simulation->add_group(group);
  return simulation;
}

size_t members_of(const Simulation& simulation) {
  return simulation.find_group(1)->members().size();
}

// Departures are a Poisson process of leave_rate per member: four members at 0.5 a minute each
// leave first after 30 s on average. The leaver walks off to leave_distance from the centre.
TEST(GroupTurnover, MembersLeaveAtTheRateAndWalkAway) {
  GroupTurnoverSpec turnover;
  turnover.leave_rate_per_min = 0.5;
  double first_departures_s = 0.0;
  int seeds = 0;
  double farthest_m = 0.0;
  for (uint64_t seed = 1; seed <= 40; ++seed) {
    auto simulation = turnover_world(seed, 4, turnover);
    while (members_of(*simulation) == 4 && simulation->time_s() < 600.0) {
      simulation->step();
    }
    ASSERT_EQ(members_of(*simulation), 3u) << "seed " << seed;
    first_departures_s += simulation->time_s();
    ++seeds;
    model::ObjectId leaver = model::kNoObject;
    for (const Human* human : simulation->humans()) {
      leaver = human->group_id() == model::kNoObject ? human->id() : leaver;
    }
    ASSERT_NE(leaver, model::kNoObject);
    for (int i = 0; i < 300; ++i) {  // 15 s to walk 4 m
      simulation->step();
    }
    const double away_m = (simulation->find_human(leaver)->pose().position - kCentre).norm();
    farthest_m = std::max(farthest_m, away_m);
    EXPECT_GT(away_m, 2.0) << "seed " << seed;
  }
  const double mean_s = first_departures_s / seeds;
  std::printf("| first departure of four at 0.5 a minute each | mean %.1f s (expected 30) |\n",
              mean_s);
  EXPECT_GT(mean_s, 20.0);
  EXPECT_LT(mean_s, 42.0);
  std::printf("| farthest leaver from the centre after 15 s | %.2f m (leave_distance 4) |\n",
              farthest_m);
  EXPECT_GT(farthest_m, 3.0);
}

// Nobody leaves a group of min_members.
TEST(GroupTurnover, NobodyLeavesASmallestGroup) {
  GroupTurnoverSpec turnover;
  turnover.leave_rate_per_min = 6.0;
  turnover.min_members = 3;
  auto simulation = turnover_world(3, 4, turnover);
  for (int i = 0; i < 2400; ++i) {
    simulation->step();
  }
  EXPECT_EQ(members_of(*simulation), 3u);
}

// A passer-by within join_radius joins at join_rate, the nearest first, up to max_members; one
// beyond the radius never does.
TEST(GroupTurnover, PassersByJoinUpToTheLargestGroup) {
  GroupTurnoverSpec turnover;
  turnover.join_rate_per_min = 2.0;
  turnover.join_radius_m = 3.0;
  turnover.max_members = 4;
  int joined_within_a_minute = 0;
  for (uint64_t seed = 1; seed <= 20; ++seed) {
    auto simulation =
        turnover_world(seed, 2, turnover, {{7.5, 5.0}, {5.0, 2.3}, {5.0, 8.6}, {1.0, 1.0}});
    while (members_of(*simulation) == 2 && simulation->time_s() < 60.0) {
      simulation->step();
    }
    joined_within_a_minute += members_of(*simulation) > 2 ? 1 : 0;
    if (members_of(*simulation) > 2) {
      EXPECT_EQ(simulation->find_human(20)->group_id(), 1u) << "seed " << seed;  // nearest
    }
    while (simulation->time_s() < 600.0) {
      simulation->step();
    }
    EXPECT_EQ(members_of(*simulation), 4u) << "seed " << seed;
    EXPECT_EQ(simulation->find_human(22)->group_id(), model::kNoObject) << "seed " << seed;
    EXPECT_EQ(simulation->find_human(23)->group_id(), model::kNoObject) << "seed " << seed;
  }
  // 1 - exp(-2) = 0.86 of the seeds.
  std::printf(
      "| a passer-by joins a pair within a minute at 2 a minute | %d of 20 (expected 17) |\n",
      joined_within_a_minute);
  EXPECT_GE(joined_within_a_minute, 13);
}

// The same seed gives the same comings and goings; the default spec keeps the group as it is.
TEST(GroupTurnover, SameSeedSameTurnoverAndOffByDefault) {
  GroupTurnoverSpec turnover;
  turnover.leave_rate_per_min = 1.0;
  turnover.join_rate_per_min = 1.0;
  auto history = [&](uint64_t seed, const GroupTurnoverSpec& spec) {
    auto simulation = turnover_world(seed, 4, spec, {{7.0, 5.0}, {3.0, 3.0}});
    std::string members;
    for (int i = 0; i < 2400; ++i) {
      simulation->step();
      if (i % 100 == 0) {
        for (model::ObjectId id : simulation->find_group(1)->members()) {
          members += std::to_string(id) + " ";
        }
        members += "| ";
      }
    }
    return members;
  };
  EXPECT_EQ(history(5, turnover), history(5, turnover));
  EXPECT_NE(history(5, turnover), history(6, turnover));
  const std::string still = history(5, GroupTurnoverSpec{});
  EXPECT_EQ(still.find("20"), std::string::npos);
  EXPECT_EQ(still.substr(0, still.find('|')), "10 11 12 13 ");
  EXPECT_EQ(still.substr(still.rfind('|', still.size() - 3) + 2), "10 11 12 13 | ");
}

// scenes/gathering.yaml over two minutes: its two circles (five and four people) lose members and
// take in people standing alone or leaving another group, while the pairs and the row, without
// turnover, keep theirs. Membership is looked at every second.
TEST(GroupTurnover, TheShippedGatheringChangesItsLargerGroups) {
  const auto simulation = build_simulation(
      load_scene_file(std::string(ARI_SOURCE_DIR) + "/scenes/gathering.yaml"), SimulationConfig{});
  std::map<model::ObjectId, std::set<model::ObjectId>> members;
  std::map<model::ObjectId, int> departures, arrivals;
  size_t largest = 0;
  for (int step = 0; step <= 2400; ++step) {
    if (step % 20 == 0) {
      for (const auto& group : simulation->groups()) {
        const std::vector<model::ObjectId>& now = group->members();
        std::set<model::ObjectId>& before = members[group->id()];
        const std::set<model::ObjectId> current(now.begin(), now.end());
        if (step > 0) {
          for (model::ObjectId id : before) {
            departures[group->id()] += current.count(id) == 0 ? 1 : 0;
          }
          for (model::ObjectId id : current) {
            arrivals[group->id()] += before.count(id) == 0 ? 1 : 0;
          }
        }
        before = current;
        largest = std::max(largest, current.size());
      }
    }
    simulation->step();
  }
  for (model::ObjectId circle : {1, 2}) {
    EXPECT_GE(departures[circle], 1) << "group " << circle;
    EXPECT_GE(arrivals[circle], 1) << "group " << circle;
  }
  for (model::ObjectId steady : {3, 4, 5}) {
    EXPECT_EQ(departures[steady] + arrivals[steady], 0) << "group " << steady;
  }
  EXPECT_GE(largest, 5u);
  std::printf("gathering, 120 s: group 1 lost %d and took in %d, group 2 lost %d and took in %d\n",
              departures[1], arrivals[1], departures[2], arrivals[2]);
}

TEST(GroupTurnover, RefusesAMaximumNotAboveTheMinimum) {
  GroupTurnoverSpec turnover;
  turnover.min_members = 4;
  turnover.max_members = 3;
  try {
    turnover_world(1, 4, turnover);
    FAIL() << "accepted";
  } catch (const core::RequestError& e) {
    EXPECT_NE(std::string(e.what()).find("turnover.max_members"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("an integer above min_members"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace ari_social_sim::world
