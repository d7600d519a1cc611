#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "../common/data_sets.hpp"
#include "../world/scene_builders.hpp"
#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/perception/gcff.hpp"
#include "ari_social_sim/world/formation_layout.hpp"
#include "ari_social_sim/world/group_navigation.hpp"
#include "ari_social_sim/world/simulation.hpp"
#include "recorded_formations.hpp"

// The world's groups of 2, 3 and 4 in each arrangement against the recorded F-formations (issues
// 17 and 31): the median of each member distance to the o-space centre, pair distance and facing
// offset falls within the recorded 10th-90th percentile, and the world's 10th-90th band covers at
// least half of the recorded one; members of standing groups shift and turn as recorded ones do.
// Printed for docs/world.md.

namespace ari_social_sim::perception {
namespace {

using model::Arrangement;

constexpr double kPerceptionStrideM = test::kComparisonStrideM;
constexpr int kSeedsPerCase = 20;
constexpr double kSettleS = 30.0;
constexpr double kJoinS = 30.0;
// Two members' centres closer than this and their bodies would overlap.
const double kBodiesApartM = 2.0 * world::HumanMotionParams{}.body_radius_m;

// A group of `size` in `arrangement` about to form, members started at random 0.5-2.5 m from the
// centre, with the world's defaults (spacing by size, stances, shifts).
struct FormingGroup {
  std::unique_ptr<world::Simulation> simulation;
  std::vector<model::ObjectId> members;
};

FormingGroup forming_group(Arrangement arrangement, int size, uint64_t seed,
                           const std::function<void(world::GroupSpec&)>& adjust = {}) {
  FormingGroup group;
  group.simulation = std::make_unique<world::Simulation>(world::test::square_room(8.0),
                                                         world::SimulationConfig{0.05, seed, 0.05});
  core::Rng rng(seed);
  world::GroupSpec spec;
  spec.id = 1;
  spec.centre = {4.0, 4.0};
  spec.arrangement = arrangement;
  if (adjust) {
    adjust(spec);
  }
  while (static_cast<int>(spec.members.size()) < size) {
    world::HumanSpec human;
    human.id = 10 + static_cast<model::ObjectId>(spec.members.size());
    const double bearing = rng.uniform(-M_PI, M_PI);
    human.pose = {
        spec.centre + rng.uniform(0.5, 2.5) * Eigen::Vector2d(std::cos(bearing), std::sin(bearing)),
        rng.uniform(-M_PI, M_PI)};
    try {
      group.simulation->add_human(human);
      spec.members.push_back(human.id);
    } catch (const core::RequestError&) {
      // Overlapping draw: another place.
    }
  }
  group.simulation->add_group(spec);
  group.members = spec.members;
  return group;
}

void run_until(world::Simulation& simulation, double time_s) {
  while (simulation.time_s() < time_s - 1e-9) {
    simulation.step();
  }
}

FormationGeometry geometry_of(const FormingGroup& group) {
  std::vector<GcffPerson> members;
  for (model::ObjectId id : group.members) {
    const core::Pose2& pose = group.simulation->find_human(id)->pose();
    members.push_back({std::to_string(id), pose.position.x(), pose.position.y(), pose.theta});
  }
  return formation_geometry(members, kPerceptionStrideM);
}

// The group's facing offsets (deg) as the recordings it is compared with would have marked them:
// measured with every facing rounded to each data set's annotation step, each set counted as
// often as it has groups in `reference`. The recorded facings are that coarse (CoffeeBreak marks
// quarter turns), which alone spreads a square stance by up to 45 degrees.
std::vector<double> annotated_offsets_deg(const std::vector<core::Pose2>& poses,
                                          const test::FormationSpread& reference) {
  std::vector<double> offsets;
  for (const auto& [set, groups] : reference.groups_of_set) {
    const double step = test::annotated_facing_step_rad(set);
    std::vector<GcffPerson> members;
    for (size_t i = 0; i < poses.size(); ++i) {
      members.push_back({std::to_string(i), poses[i].position.x(), poses[i].position.y(),
                         test::annotated_facing(poses[i].theta, step)});
    }
    for (const double offset : formation_geometry(members, kPerceptionStrideM).facing_offsets_rad) {
      offsets.insert(offsets.end(), static_cast<size_t>(groups), offset * 180.0 / M_PI);
    }
  }
  return offsets;
}

// Least distance (m) between two members' centres.
double closest_pair_m(const FormingGroup& group) {
  double closest = std::numeric_limits<double>::infinity();
  for (size_t a = 0; a < group.members.size(); ++a) {
    for (size_t b = a + 1; b < group.members.size(); ++b) {
      closest = std::min(closest, (group.simulation->find_human(group.members[a])->pose().position -
                                   group.simulation->find_human(group.members[b])->pose().position)
                                      .norm());
    }
  }
  return closest;
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
      for (const auto& [set, groups] : spread.groups_of_set) {
        reference.groups_of_set[set] += groups;
      }
      reference.centre_m.insert(reference.centre_m.end(), spread.centre_m.begin(),
                                spread.centre_m.end());
      reference.pair_m.insert(reference.pair_m.end(), spread.pair_m.begin(), spread.pair_m.end());
      reference.offset_deg.insert(reference.offset_deg.end(), spread.offset_deg.begin(),
                                  spread.offset_deg.end());
    }
  }
  return "any " + arrangement;
}

// The bands the world's groups cover less than half of, and why (docs/world.md): the recorded
// facings of groups of three spread over 1-94 degrees, widened in part by the annotation
// (CoffeeBreak marks facings in quarter turns, Synth in steps of 15 degrees), and recorded
// side-by-side pairs stand from 0.40 to 1.19 m apart, where the world's rows keep a shoulder
// spacing near 0.6 m. They are held to a fifth of the recorded band.
double least_overlap(int size, const std::string& compared, const std::string& what) {
  constexpr double kLeastOverlap = 0.5;
  constexpr double kKnownShortOverlap = 0.2;
  const bool facing_of_three = size == 3 && what == "facing off the centre";
  const bool side_by_side_pair = compared == "2 side-by-side";
  return facing_of_three || side_by_side_pair ? kKnownShortOverlap : kLeastOverlap;
}

// The part of a recorded band of distances between members that two bodies can reach: a tenth
// of the recorded vis-a-vis pairs stand less than 0.20 m apart, centre to centre, where two
// people's bodies would overlap; annotated positions err by that much, people do not.
test::Band reachable(test::Band recorded, const std::string& what) {
  if (what == "distance between members") {
    recorded.low = std::max(recorded.low, kBodiesApartM);
  }
  return recorded;
}

// "median [10th-90th]" of world values, the same of recorded ones, and how much of the recorded
// band the world's covers (of its reachable part, for distances between members).
std::string band_cell(const std::vector<double>& world_values,
                      const std::vector<double>& recorded_values, const char* number,
                      const std::string& what = "") {
  const std::string format = std::string(number) + " [" + number + "-" + number + "] / " + number +
                             " [" + number + "-" + number + "], %.0f %%";
  const test::Band world = test::band_of(world_values);
  const test::Band recorded = test::band_of(recorded_values);
  char text[160];
  std::snprintf(text, sizeof(text), format.c_str(), test::percentile(world_values, 0.5), world.low,
                world.high, test::percentile(recorded_values, 0.5), recorded.low, recorded.high,
                100.0 * test::band_overlap(world, reachable(recorded, what)));
  return text;
}

// Side-by-side pairs with the row manners that match the recordings (row_spacing_spread 0.6,
// row_facing_spread 35 deg): every band covers at least half of the recorded pairs' (docs/world.md
// section 4.5: 54, 61 and 83 %). Not the default: GCFF finds such rows less often.
TEST(WorldFormations, RowMannersSpreadSideBySidePairsAsRecorded) {
  ARI_SKIP_WITHOUT_DATA_SET("fformation");
  const test::FormationSpread recorded = test::recorded_formation_spreads().at({2, "side-by-side"});
  test::FormationSpread world;
  for (int seed = 1; seed <= kSeedsPerCase; ++seed) {
    const FormingGroup group = forming_group(
        Arrangement::kSideBySide, 2, static_cast<uint64_t>(seed), [](world::GroupSpec& spec) {
          spec.row_spacing_spread = 0.6;
          spec.row_facing_spread_deg = 35.0;
        });
    run_until(*group.simulation, kSettleS);
    world.add(geometry_of(group));
    EXPECT_GT(closest_pair_m(group), kBodiesApartM) << "seed " << seed;
  }
  std::printf("side-by-side pairs with row manners: %s | %s | %s\n",
              band_cell(world.centre_m, recorded.centre_m, "%.2f").c_str(),
              band_cell(world.pair_m, recorded.pair_m, "%.2f").c_str(),
              band_cell(world.offset_deg, recorded.offset_deg, "%.0f").c_str());
  for (const auto& [world_values, recorded_values] :
       {std::pair{world.centre_m, recorded.centre_m}, std::pair{world.pair_m, recorded.pair_m},
        std::pair{world.offset_deg, recorded.offset_deg}}) {
    EXPECT_GE(test::band_overlap(test::band_of(world_values), test::band_of(recorded_values)), 0.5);
  }
}

// Each member's distance to the o-space centre, pair distance and facing offset, world against
// recordings: the world's median within the recorded 10th-90th percentile, and, where groups of
// the same size and class were recorded, the world's 10th-90th band covering at least half of
// the recorded one (overlap = |intersection| / |recorded band|), but for the bands least_overlap
// names. Members' bodies never overlap.
TEST(WorldFormations, FallWithinTheRecordedSpread) {
  ARI_SKIP_WITHOUT_DATA_SET("fformation");
  const std::map<test::SpreadKey, test::FormationSpread> recorded =
      test::recorded_formation_spreads();
  std::printf(
      "| size | arrangement | compared with (groups) | to centre (m): world median [10-90 %%] / "
      "recorded, overlap | between members (m) | facing off the centre (deg) | the same, the "
      "world's facings rounded as annotated |\n"
      "|---|---|---|---|---|---|---|\n");
  for (Arrangement arrangement : {Arrangement::kCircle, Arrangement::kVisAVis, Arrangement::kLShape,
                                  Arrangement::kSideBySide}) {
    for (int size = 2; size <= 4; ++size) {
      test::FormationSpread world;
      std::map<std::string, int> classified;
      std::vector<std::vector<core::Pose2>> settled;
      for (int seed = 1; seed <= kSeedsPerCase; ++seed) {
        const FormingGroup group = forming_group(arrangement, size, static_cast<uint64_t>(seed));
        run_until(*group.simulation, kSettleS);
        settled.emplace_back();
        for (model::ObjectId id : group.members) {
          settled.back().push_back(group.simulation->find_human(id)->pose());
        }
        const FormationGeometry geometry = geometry_of(group);
        world.add(geometry);
        ++classified[model::to_string(geometry.arrangement)];
        EXPECT_GT(closest_pair_m(group), kBodiesApartM)
            << size << " " << model::to_string(arrangement) << " seed " << seed;
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
      std::vector<double> annotated_deg;
      for (const std::vector<core::Pose2>& poses : settled) {
        const std::vector<double> offsets = annotated_offsets_deg(poses, reference);
        annotated_deg.insert(annotated_deg.end(), offsets.begin(), offsets.end());
      }
      std::printf(
          "| %d | %s | %s (%d) | %s | %s | %s | %s |\n", size, model::to_string(arrangement),
          compared.c_str(), reference.groups,
          band_cell(world.centre_m, reference.centre_m, "%.2f").c_str(),
          band_cell(world.pair_m, reference.pair_m, "%.2f", "distance between members").c_str(),
          band_cell(world.offset_deg, reference.offset_deg, "%.0f").c_str(),
          band_cell(annotated_deg, reference.offset_deg, "%.0f").c_str());
      // Within the recorded 10th-90th percentile where groups of the size were recorded, and
      // their bands overlapping. No group of four was recorded: groups of four, wider than the
      // recorded groups of three as groups grow, and a side-by-side row of four, longer than any
      // recorded row, are held to the whole recorded range (docs/world.md says by how much).
      const bool same_size_recorded = compared.front() != 'a';
      const bool row_of_four = !same_size_recorded;
      const double low = row_of_four ? 0.0 : 0.1;
      const double high = row_of_four ? 1.0 : 0.9;
      auto within = [&](const std::vector<double>& world_values,
                        const std::vector<double>& recorded_values, const char* what) {
        const double median = test::percentile(world_values, 0.5);
        if (row_of_four) {
          std::printf("  %d %s, %s: %.2f in the recorded range %.2f-%.2f\n", size, name.c_str(),
                      what, median, test::percentile(recorded_values, low),
                      test::percentile(recorded_values, high));
        }
        EXPECT_GE(median, test::percentile(recorded_values, low))
            << size << " " << model::to_string(arrangement) << ": " << what;
        EXPECT_LE(median, test::percentile(recorded_values, high))
            << size << " " << model::to_string(arrangement) << ": " << what;
        if (same_size_recorded) {
          EXPECT_GE(test::band_overlap(test::band_of(world_values),
                                       reachable(test::band_of(recorded_values), what)),
                    least_overlap(size, compared, what))
              << size << " " << model::to_string(arrangement) << ": " << what;
        }
      };
      within(world.centre_m, reference.centre_m, "distance to the o-space centre");
      within(world.pair_m, reference.pair_m, "distance between members");
      within(world.offset_deg, reference.offset_deg, "facing off the centre");
    }
  }
}

// Circles of 2 to 6 settled with the default spacing by size, without the groups' and members'
// own spacing: the median distance between neighbours grows with the group up to four; circles of
// five and six keep at least 0.8 of their default spacing (0.9 m). No recorded group is larger
// than three, so this is the spacing the defaults give, not a comparison.
TEST(WorldFormations, SpacingGrowsWithTheGroup) {
  std::printf(
      "| size | neighbours apart (m): median [10-90 %%] | to the o-space centre (m) |\n"
      "|---|---|---|\n");
  double previous_median = 0.0;
  for (int size = 2; size <= 6; ++size) {
    std::vector<double> neighbours, centre;
    for (int seed = 1; seed <= kSeedsPerCase; ++seed) {
      const FormingGroup group =
          forming_group(Arrangement::kCircle, size, static_cast<uint64_t>(seed),
                        [](world::GroupSpec& spec) { spec.spacing_spread = 0.0; });
      run_until(*group.simulation, kSettleS);
      const world::GroupNavigation& navigation = *group.simulation->find_group(1);
      for (model::ObjectId id : group.members) {
        const Eigen::Vector2d p = group.simulation->find_human(id)->pose().position;
        centre.push_back((p - navigation.centre()).norm());
        double nearest = std::numeric_limits<double>::infinity();
        for (model::ObjectId other : group.members) {
          if (other != id) {
            nearest = std::min(nearest,
                               (group.simulation->find_human(other)->pose().position - p).norm());
          }
        }
        neighbours.push_back(nearest);
      }
      EXPECT_GT(closest_pair_m(group), kBodiesApartM) << size << " " << seed;
    }
    const double median = test::percentile(neighbours, 0.5);
    std::printf("| %d | %.2f [%.2f-%.2f] | %.2f [%.2f-%.2f] |\n", size, median,
                test::percentile(neighbours, 0.1), test::percentile(neighbours, 0.9),
                test::percentile(centre, 0.5), test::percentile(centre, 0.1),
                test::percentile(centre, 0.9));
    if (size <= 4) {
      EXPECT_GT(median, previous_median) << size;
    } else {
      EXPECT_GT(median, 0.8 * world::GroupNavigation::default_member_spacing_m(size)) << size;
    }
    previous_median = median;
  }
}

// How members of settled groups move, looked at every 5 s from 30 s to 90 s: displacement and
// turn of each member between two looks.
test::MemberMotion world_motion(int size, int seeds) {
  constexpr double kLookEveryS = 5.0;
  constexpr double kUntilS = 90.0;
  test::MemberMotion motion;
  for (Arrangement arrangement : {Arrangement::kCircle, Arrangement::kVisAVis, Arrangement::kLShape,
                                  Arrangement::kSideBySide}) {
    for (int seed = 1; seed <= seeds; ++seed) {
      FormingGroup group = forming_group(arrangement, size, static_cast<uint64_t>(seed));
      run_until(*group.simulation, kSettleS);
      std::vector<core::Pose2> before;
      for (model::ObjectId id : group.members) {
        before.push_back(group.simulation->find_human(id)->pose());
      }
      for (double look = kSettleS + kLookEveryS; look <= kUntilS + 1e-9; look += kLookEveryS) {
        run_until(*group.simulation, look);
        for (size_t k = 0; k < group.members.size(); ++k) {
          const core::Pose2 now = group.simulation->find_human(group.members[k])->pose();
          ++motion.members;
          motion.displacement_m.push_back((now.position - before[k].position).norm());
          motion.turn_deg.push_back(std::abs(core::angle_difference(now.theta, before[k].theta)) *
                                    180.0 / M_PI);
          motion.quadrant_turn_deg.push_back(test::quadrant_turn_deg(before[k].theta, now.theta));
          before[k] = now;
        }
      }
    }
  }
  return motion;
}

double mean_of(const std::vector<double>& values) {
  double sum = 0.0;
  for (double value : values) {
    sum += value;
  }
  return values.empty() ? 0.0 : sum / static_cast<double>(values.size());
}

// Members of standing groups of two and three against the recorded CoffeeBreak members between
// consecutive annotated frames (the files give no time between frames; issue 31 reads them as
// 5 s apart, and so do we). Displacement: the world's 10th-90th band covers at least half of the
// recorded one. Turning: the recordings mark facings in steps of 90 degrees, so the world's
// facings are rounded alike before they are compared; rounding keeps the mean turn (a turn of x
// crosses a quadrant's edge with probability x / 90), which is compared within a factor of two,
// and the bands of the rounded turns overlap by half. Displacement median at least 1 cm: the
// members do not stand still.
TEST(WorldFormations, MembersShiftAndTurnAsRecordedOnesDo) {
  ARI_SKIP_WITHOUT_DATA_SET("fformation");
  constexpr double kLeastOverlap = 0.5;
  const std::map<size_t, test::MemberMotion> recorded = test::recorded_member_motion();
  std::printf(
      "| size | members x looks: world / recorded | displacement per 5 s (m): world median "
      "[10-90 %%] / recorded, overlap | turn per 5 s (deg): world median [10-90 %%], mean | "
      "turn rounded to 90 deg: world mean / recorded mean, band overlap |\n"
      "|---|---|---|---|---|\n");
  for (int size = 2; size <= 3; ++size) {
    const test::MemberMotion world = world_motion(size, 5);
    const test::MemberMotion& real = recorded.at(static_cast<size_t>(size));
    const double displacement_overlap =
        test::band_overlap(test::band_of(world.displacement_m), test::band_of(real.displacement_m));
    const double rounded_overlap = test::band_overlap(test::band_of(world.quadrant_turn_deg),
                                                      test::band_of(real.quadrant_turn_deg));
    const test::Band turn = test::band_of(world.turn_deg);
    std::printf("| %d | %d / %d | %s | %.0f [%.0f-%.0f], %.0f | %.1f / %.1f, %.0f %% |\n", size,
                world.members, real.members,
                band_cell(world.displacement_m, real.displacement_m, "%.3f").c_str(),
                test::percentile(world.turn_deg, 0.5), turn.low, turn.high, mean_of(world.turn_deg),
                mean_of(world.quadrant_turn_deg), mean_of(real.quadrant_turn_deg),
                100.0 * rounded_overlap);
    EXPECT_GE(displacement_overlap, kLeastOverlap) << size;
    EXPECT_GE(rounded_overlap, kLeastOverlap) << size;
    EXPECT_GT(test::percentile(world.displacement_m, 0.5), 0.01) << size;
    EXPECT_GT(mean_of(world.quadrant_turn_deg), 0.5 * mean_of(real.quadrant_turn_deg)) << size;
    EXPECT_LT(mean_of(world.quadrant_turn_deg), 2.0 * mean_of(real.quadrant_turn_deg)) << size;
  }
}

// Same seed, same shifts: two runs of a group of three agree to the bit after a minute.
TEST(WorldFormations, ShiftsAreTheSameForTheSameSeed) {
  FormingGroup a = forming_group(Arrangement::kCircle, 3, 7);
  FormingGroup b = forming_group(Arrangement::kCircle, 3, 7);
  run_until(*a.simulation, 60.0);
  run_until(*b.simulation, 60.0);
  for (size_t k = 0; k < a.members.size(); ++k) {
    const core::Pose2 pa = a.simulation->find_human(a.members[k])->pose();
    const core::Pose2 pb = b.simulation->find_human(b.members[k])->pose();
    EXPECT_EQ(pa.position, pb.position);
    EXPECT_EQ(pa.theta, pb.theta);
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
      const double other_radius = world::GroupNavigation::ospace_radius_for(
          3, world::GroupNavigation::default_member_spacing_m(3), 0.45);
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
