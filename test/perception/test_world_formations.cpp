#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "../common/data_sets.hpp"
#include "../world/scene_builders.hpp"
#include "ari_social_sim/perception/gcff.hpp"
#include "ari_social_sim/world/formation_layout.hpp"
#include "ari_social_sim/world/group_navigation.hpp"
#include "ari_social_sim/world/simulation.hpp"
#include "recorded_formations.hpp"

// The world's groups of 2, 3 and 4 in each arrangement against the recorded F-formations (issue
// 17): the median of each member distance to the o-space centre, pair distance and facing offset
// falls within the recorded 10th-90th percentile. Printed for docs/world.md.

namespace ari_social_sim::perception {
namespace {

using model::Arrangement;

constexpr double kPerceptionStrideM = test::kComparisonStrideM;
constexpr int kSeedsPerCase = 20;
constexpr double kSettleS = 30.0;
constexpr double kJoinS = 30.0;

// One settled group of `size` in `arrangement`, members started at random 0.5-2.5 m from the
// centre, with the world's default spacing and stances.
FormationGeometry settled_group(Arrangement arrangement, int size, uint64_t seed) {
  world::Simulation simulation(world::test::square_room(8.0),
                               world::SimulationConfig{0.05, seed, 0.05});
  core::Rng rng(seed);
  world::GroupSpec spec;
  spec.id = 1;
  spec.centre = {4.0, 4.0};
  spec.arrangement = arrangement;
  while (static_cast<int>(spec.members.size()) < size) {
    world::HumanSpec human;
    human.id = 10 + static_cast<model::ObjectId>(spec.members.size());
    const double bearing = rng.uniform(-M_PI, M_PI);
    human.pose = {
        spec.centre + rng.uniform(0.5, 2.5) * Eigen::Vector2d(std::cos(bearing), std::sin(bearing)),
        rng.uniform(-M_PI, M_PI)};
    try {
      simulation.add_human(human);
      spec.members.push_back(human.id);
    } catch (const core::RequestError&) {
      // Overlapping draw: another place.
    }
  }
  simulation.add_group(spec);
  while (simulation.time_s() < kSettleS - 1e-9) {
    simulation.step();
  }
  std::vector<GcffPerson> members;
  for (model::ObjectId id : spec.members) {
    const core::Pose2& pose = simulation.find_human(id)->pose();
    members.push_back({std::to_string(id), pose.position.x(), pose.position.y(), pose.theta});
  }
  return formation_geometry(members, kPerceptionStrideM);
}

// The recorded groups a world group is compared with: those of the same size and arrangement
// when at least 20 were recorded; else those of the arrangement in groups of any size (no group
// of four was recorded: a circle of four is compared with the circles of three).
std::string reference_of(const std::map<test::SpreadKey, test::FormationSpread>& recorded,
                         size_t size, const std::string& arrangement,
                         test::FormationSpread& reference) {
  const auto exact = recorded.find({size, arrangement});
  if (exact != recorded.end() && exact->second.groups >= 20) {
    reference = exact->second;
    return std::to_string(size) + " " + arrangement;
  }
  reference = {};
  for (const auto& [key, spread] : recorded) {
    if (key.second == arrangement) {
      reference.groups += spread.groups;
      reference.centre_m.insert(reference.centre_m.end(), spread.centre_m.begin(),
                                spread.centre_m.end());
      reference.pair_m.insert(reference.pair_m.end(), spread.pair_m.begin(), spread.pair_m.end());
      reference.offset_deg.insert(reference.offset_deg.end(), spread.offset_deg.begin(),
                                  spread.offset_deg.end());
    }
  }
  return "any " + arrangement;
}

TEST(WorldFormations, FallWithinTheRecordedSpread) {
  ARI_SKIP_WITHOUT_DATA_SET("fformation");
  const std::map<test::SpreadKey, test::FormationSpread> recorded =
      test::recorded_formation_spreads();
  std::printf(
      "| size | arrangement | compared with (groups) | to centre (m): world median, recorded 10-90 "
      "%% | between members (m) | facing off the centre (deg) |\n|---|---|---|---|---|---|\n");
  for (Arrangement arrangement : {Arrangement::kCircle, Arrangement::kVisAVis, Arrangement::kLShape,
                                  Arrangement::kSideBySide}) {
    for (int size = 2; size <= 4; ++size) {
      test::FormationSpread world;
      std::map<std::string, int> classified;
      for (int seed = 1; seed <= kSeedsPerCase; ++seed) {
        const FormationGeometry geometry =
            settled_group(arrangement, size, static_cast<uint64_t>(seed));
        world.add(geometry);
        ++classified[model::to_string(geometry.arrangement)];
      }
      // Compared like with like: the recorded groups the same rule classifies as the world's
      // groups mostly are (a circle of two stands vis-a-vis; three or four in two rows facing
      // each other are a circle by it).
      const std::string name =
          std::max_element(classified.begin(), classified.end(), [](const auto& a, const auto& b) {
            return a.second < b.second;
          })->first;
      test::FormationSpread reference;
      const std::string compared = reference_of(recorded, size, name, reference);
      ASSERT_GT(reference.groups, 0) << compared;
      auto cell = [](const std::vector<double>& world_values,
                     const std::vector<double>& recorded_values, const char* format) {
        char text[96];
        std::snprintf(text, sizeof(text), format, test::percentile(world_values, 0.5),
                      test::percentile(recorded_values, 0.1),
                      test::percentile(recorded_values, 0.9));
        return std::string(text);
      };
      std::printf("| %d | %s | %s (%d) | %s | %s | %s |\n", size, model::to_string(arrangement),
                  compared.c_str(), reference.groups,
                  cell(world.centre_m, reference.centre_m, "%.2f in %.2f-%.2f").c_str(),
                  cell(world.pair_m, reference.pair_m, "%.2f in %.2f-%.2f").c_str(),
                  cell(world.offset_deg, reference.offset_deg, "%.0f in %.0f-%.0f").c_str());
      // Within the recorded 10th-90th percentile, but for a side-by-side row of four: no
      // recorded side-by-side group is longer than three, and a row of four is wider than most of
      // them, so it is held to the whole recorded range (docs/world.md says by how much).
      const bool row_of_four = size == 4 && name == "side-by-side";
      const double low = row_of_four ? 0.0 : 0.1;
      const double high = row_of_four ? 1.0 : 0.9;
      auto within = [&](const std::vector<double>& world_values,
                        const std::vector<double>& recorded_values, const char* what) {
        const double median = test::percentile(world_values, 0.5);
        if (row_of_four) {
          std::printf("  row of four, %s: %.2f in the recorded range %.2f-%.2f\n", what, median,
                      test::percentile(recorded_values, low),
                      test::percentile(recorded_values, high));
        }
        EXPECT_GE(median, test::percentile(recorded_values, low))
            << size << " " << model::to_string(arrangement) << ": " << what;
        EXPECT_LE(median, test::percentile(recorded_values, high))
            << size << " " << model::to_string(arrangement) << ": " << what;
      };
      within(world.centre_m, reference.centre_m, "distance to the o-space centre");
      within(world.pair_m, reference.pair_m, "distance between members");
      within(world.offset_deg, reference.offset_deg, "facing off the centre");
    }
  }
}

// A human joining a group of 2, 3 or 4 (/sim/join_group) from 3-5 m away, with another group
// of three standing 3.5-4.5 m from the first: after 20 s GCFF on the ground truth (perception's
// stride and MDL) puts the newcomer with every member, in at least 98 of 100 seeded episodes per
// size, and the newcomer never enters the other group's o-space.
TEST(WorldFormations, AHumanJoiningIsCountedInTheGroup) {
  constexpr int kEpisodes = 100;
  GcffParams params;
  params.stride = kPerceptionStrideM;
  params.mdl = 0.8;
  GcffDetector detector(params);
  for (int size = 2; size <= 4; ++size) {
    int counted = 0;
    int intrusions = 0;
    for (int episode = 0; episode < kEpisodes; ++episode) {
      const uint64_t seed = 1000 * size + episode;
      world::Simulation simulation(world::test::square_room(8.0),
                                   world::SimulationConfig{0.05, seed, 0.05});
      core::Rng rng(seed);
      const Arrangement arrangements[] = {Arrangement::kCircle, Arrangement::kVisAVis,
                                          Arrangement::kLShape, Arrangement::kSideBySide};
      // Two groups at their places: the one joined, and another to keep out of.
      auto place_group = [&](model::ObjectId id, model::ObjectId first, int members,
                             const Eigen::Vector2d& centre, Arrangement arrangement) {
        world::GroupSpec spec;
        spec.id = id;
        spec.centre = centre;
        spec.arrangement = arrangement;
        spec.heading_rad = rng.uniform(-M_PI, M_PI);
        const std::vector<world::FormationSlot> slots =
            world::formation_slots(world::GroupNavigation::settled_shape(spec, members), members);
        for (int k = 0; k < members; ++k) {
          world::HumanSpec human;
          human.id = first + static_cast<model::ObjectId>(k);
          human.pose = {slots[k].position, slots[k].facing_rad};
          simulation.add_human(human);
          spec.members.push_back(human.id);
        }
        simulation.add_group(spec);
        return spec;
      };
      const Eigen::Vector2d centre(rng.uniform(3.0, 5.0), rng.uniform(3.0, 5.0));
      const world::GroupSpec joined =
          place_group(1, 10, size, centre, arrangements[rng.uniform_index(4)]);
      const double other_bearing = rng.uniform(-M_PI, M_PI);
      const Eigen::Vector2d other_centre =
          centre +
          rng.uniform(3.5, 4.5) * Eigen::Vector2d(std::cos(other_bearing), std::sin(other_bearing));
      const bool other_fits =
          (other_centre.array() > 1.2).all() && (other_centre.array() < 6.8).all();
      if (other_fits) {
        place_group(2, 20, 3, other_centre, Arrangement::kCircle);
      }
      // The newcomer, 3-5 m from the centre on the side away from the other group.
      world::HumanSpec newcomer;
      newcomer.id = 30;
      for (int draw = 0; draw < 100; ++draw) {
        const double bearing = other_bearing + M_PI + rng.uniform(-1.2, 1.2);
        const Eigen::Vector2d at =
            centre + rng.uniform(3.0, 5.0) * Eigen::Vector2d(std::cos(bearing), std::sin(bearing));
        newcomer.pose = {at, rng.uniform(-M_PI, M_PI)};
        if ((at.array() > 0.5).all() && (at.array() < 7.5).all()) {
          break;
        }
      }
      simulation.add_human(newcomer);
      simulation.join_group(1, 30);
      const double other_radius = world::GroupNavigation::ospace_radius_for(3, 0.9, 0.45);
      bool intruded = false;
      while (simulation.time_s() < kJoinS - 1e-9) {
        simulation.step();
        const Eigen::Vector2d p = simulation.find_human(30)->pose().position;
        intruded = intruded || (other_fits && (p - other_centre).norm() < other_radius);
      }
      intrusions += intruded ? 1 : 0;
      std::vector<GcffPerson> people;
      for (const world::Human* human : simulation.humans()) {
        people.push_back({std::to_string(human->id()), human->pose().position.x(),
                          human->pose().position.y(), human->pose().theta});
      }
      const GcffResult result = detector.detect(people);
      // People are listed by id: the members 10.., then the other group 20.., then 30 last.
      const int newcomer_label = result.labels.back();
      bool together = true;
      for (size_t k = 0; k < joined.members.size(); ++k) {
        together = together && result.labels[k] == newcomer_label;
      }
      counted += together ? 1 : 0;
    }
    std::printf(
        "a human joining a group of %d: GCFF counts them in %d of %d, %d entered the "
        "other group's o-space\n",
        size, counted, kEpisodes, intrusions);
    EXPECT_GE(counted, 98) << "groups of " << size;
    EXPECT_EQ(intrusions, 0) << "groups of " << size;
  }
}

}  // namespace
}  // namespace ari_social_sim::perception
