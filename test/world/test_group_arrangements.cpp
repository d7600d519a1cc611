#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/world/formation_layout.hpp"
#include "ari_social_sim/world/group_navigation.hpp"
#include "ari_social_sim/world/scene.hpp"
#include "ari_social_sim/world/service_requests.hpp"
#include "ari_social_sim/world/simulation.hpp"
#include "refusal_text.hpp"
#include "scene_builders.hpp"

namespace ari_social_sim::world {
namespace {

using model::Arrangement;

constexpr double kDeg = core::kPi / 180.0;

// A group of `size` at random places in an 8 x 8 m room around (4, 4), with `arrangement`.
struct Formed {
  std::unique_ptr<Simulation> simulation;
  model::ObjectId group{1};
};

Formed form(Arrangement arrangement, int size, uint64_t seed, double facing_spread_deg = 0.0,
            double seconds = 30.0) {
  Formed formed;
  formed.simulation =
      std::make_unique<Simulation>(test::square_room(8.0), SimulationConfig{0.05, seed, 0.05});
  core::Rng rng(seed);
  GroupSpec spec;
  spec.id = formed.group;
  spec.members = test::add_random_humans(*formed.simulation, size, 8.0, 0.5, rng);
  spec.centre = {4.0, 4.0};
  spec.arrangement = arrangement;
  test::without_manners(spec);
  spec.facing_spread_deg = facing_spread_deg;
  formed.simulation->add_group(spec);
  while (formed.simulation->time_s() < seconds - 1e-9) {
    formed.simulation->step();
  }
  return formed;
}

TEST(FormationLayout, RowsFaceTheOspaceAcrossTheirBearing) {
  FormationShape shape;
  shape.centre = {1.0, 2.0};
  shape.radius_m = 0.5;
  shape.shoulder_spacing_m = 0.6;
  shape.heading_rad = 0.0;
  // Vis-a-vis of two: at +-0.5 m along x, facing each other.
  shape.arrangement = Arrangement::kVisAVis;
  std::vector<FormationSlot> slots = formation_slots(shape, 2);
  ASSERT_EQ(slots.size(), 2u);
  EXPECT_TRUE(slots[0].position.isApprox(Eigen::Vector2d(1.5, 2.0)));
  EXPECT_NEAR(std::abs(slots[0].facing_rad), core::kPi, 1e-12);
  EXPECT_TRUE(slots[1].position.isApprox(Eigen::Vector2d(0.5, 2.0)));
  EXPECT_NEAR(slots[1].facing_rad, 0.0, 1e-12);
  // Four vis-a-vis: two pairs 0.6 m apart across the o-space.
  slots = formation_slots(shape, 4);
  EXPECT_NEAR((slots[0].position - slots[1].position).norm(), 0.6, 1e-12);
  EXPECT_NEAR((slots[0].position - slots[3].position).norm(), 1.0, 1e-12);
  // L of two: at right angles, 0.5 sqrt 2 apart; with a third, the first row is a pair centred
  // on its bearing.
  shape.arrangement = Arrangement::kLShape;
  slots = formation_slots(shape, 2);
  EXPECT_TRUE(slots[1].position.isApprox(Eigen::Vector2d(1.0, 2.5)));
  EXPECT_NEAR(core::angle_difference(slots[1].facing_rad, slots[0].facing_rad), core::kPi / 2,
              1e-12);
  slots = formation_slots(shape, 3);
  EXPECT_TRUE(slots[0].position.isApprox(Eigen::Vector2d(1.5, 1.7)));
  EXPECT_TRUE(slots[1].position.isApprox(Eigen::Vector2d(1.5, 2.3)));
  EXPECT_TRUE(slots[2].position.isApprox(Eigen::Vector2d(1.0, 2.5)));
  // Side-by-side of three: one row facing the same way, 0.6 m apart.
  shape.arrangement = Arrangement::kSideBySide;
  slots = formation_slots(shape, 3);
  for (const FormationSlot& slot : slots) {
    EXPECT_NEAR(slot.position.x(), 1.5, 1e-12);
    EXPECT_NEAR(std::abs(slot.facing_rad), core::kPi, 1e-12);
  }
  EXPECT_NEAR(slots[2].position.y() - slots[0].position.y(), 1.2, 1e-12);
}

// An L's rows stand member_spacing / sqrt(2) from the centre unless their nearest ends would come
// closer than a shoulder spacing across the corner: rows of two and one keep 0.9 / sqrt(2), two
// rows of two stand 0.3 + 0.6 / sqrt(2) m out, their corner members exactly 0.6 m apart.
TEST(FormationLayout, LRowsKeepTheirCornerClear) {
  EXPECT_NEAR(row_distance_for(Arrangement::kLShape, 2, 0.9, 0.6), 0.9 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(row_distance_for(Arrangement::kLShape, 3, 0.9, 0.6), 0.9 / std::sqrt(2.0), 1e-12);
  const double four = row_distance_for(Arrangement::kLShape, 4, 0.9, 0.6);
  EXPECT_NEAR(four, 0.3 + 0.6 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(row_distance_for(Arrangement::kVisAVis, 4, 0.9, 0.6), 0.45, 1e-12);
  EXPECT_NEAR(row_distance_for(Arrangement::kSideBySide, 4, 0.9, 0.6), 0.45, 1e-12);
  FormationShape shape;
  shape.arrangement = Arrangement::kLShape;
  shape.radius_m = four;
  shape.shoulder_spacing_m = 0.6;
  const std::vector<FormationSlot> slots = formation_slots(shape, 4);
  double closest = std::numeric_limits<double>::infinity();
  for (size_t a = 0; a < slots.size(); ++a) {
    for (size_t b = a + 1; b < slots.size(); ++b) {
      closest = std::min(closest, (slots[a].position - slots[b].position).norm());
    }
  }
  EXPECT_NEAR(closest, 0.6, 1e-12);
}

TEST(FormationLayout, SlotsGoToTheNearestParticipantsAndFixedOnesFirst) {
  std::vector<FormationSlot> slots = {{{0.0, 0.0}, 0.0}, {{1.0, 0.0}, 0.0}, {{2.0, 0.0}, 0.0}};
  const std::vector<Eigen::Vector2d> positions = {{2.1, 0.0}, {-0.1, 0.0}, {1.1, 0.0}};
  EXPECT_EQ(assign_slots(positions, slots, {}), (std::vector<size_t>{2, 0, 1}));
  // The third participant is fixed (ARI joining) and takes its nearest slot whatever it costs
  // the others.
  const std::vector<Eigen::Vector2d> crowded = {{1.0, 0.1}, {0.0, 0.1}, {1.0, -0.2}};
  EXPECT_EQ(assign_slots(crowded, slots, {2}), (std::vector<size_t>{2, 0, 1}));
  // Greedy beyond seven: every slot used once.
  std::vector<FormationSlot> many;
  std::vector<Eigen::Vector2d> people;
  for (int i = 0; i < 9; ++i) {
    many.push_back({{static_cast<double>(i), 0.0}, 0.0});
    people.push_back({8.0 - i + 0.1, 0.2});
  }
  std::vector<size_t> slot_of = assign_slots(people, many, {});
  for (int i = 0; i < 9; ++i) {
    EXPECT_EQ(slot_of[i], static_cast<size_t>(8 - i));
  }
}

// Groups of 2, 3 and 4 in every arrangement, from random starts, stand in their places within
// 10 cm and face the way their place does within 5 degrees after 30 s.
TEST(GroupArrangements, EveryArrangementFormsFromRandomStarts) {
  for (Arrangement arrangement :
       {Arrangement::kVisAVis, Arrangement::kLShape, Arrangement::kSideBySide}) {
    for (int size = 2; size <= 4; ++size) {
      for (uint64_t seed = 1; seed <= 3; ++seed) {
        SCOPED_TRACE(std::string(model::to_string(arrangement)) + " of " + std::to_string(size) +
                     ", seed " + std::to_string(seed));
        const Formed formed = form(arrangement, size, seed);
        const GroupNavigation& group = *formed.simulation->find_group(formed.group);
        EXPECT_EQ(group.arrangement(), arrangement);
        ASSERT_EQ(group.places().size(), static_cast<size_t>(size));
        for (size_t i = 0; i < group.members().size(); ++i) {
          const Human& human = *formed.simulation->find_human(group.members()[i]);
          EXPECT_LT((human.pose().position - group.places()[i].position).norm(), 0.10);
          EXPECT_LT(
              std::abs(core::angle_difference(human.pose().theta, group.places()[i].facing_rad)),
              5.0 * kDeg);
        }
      }
    }
  }
}

TEST(GroupArrangements, StancesTurnMembersOffTheFormationAsSeeded) {
  const Formed a = form(Arrangement::kSideBySide, 3, 5, 10.0);
  const Formed b = form(Arrangement::kSideBySide, 3, 5, 10.0);
  const GroupNavigation& group = *a.simulation->find_group(a.group);
  double largest = 0.0;
  for (size_t i = 0; i < group.members().size(); ++i) {
    const double theta = a.simulation->find_human(group.members()[i])->pose().theta;
    EXPECT_EQ(theta, b.simulation->find_human(group.members()[i])->pose().theta);
    largest =
        std::max(largest, std::abs(core::angle_difference(theta, group.places()[i].facing_rad)));
  }
  // Three draws of sd 10 deg: some turn is visible, none beyond 4 sd.
  EXPECT_GT(largest, 1.0 * kDeg);
  EXPECT_LT(largest, 40.0 * kDeg);
}

// D6.4 §3.4.2: a third person joining an L-shaped pair turns it into a circle; the o-space grows
// and the members make room. Leaving closes it again: two left face each other.
TEST(GroupArrangements, AHumanJoiningOpensAPlaceAndLeavingClosesIt) {
  Formed formed = form(Arrangement::kLShape, 2, 7);
  Simulation& simulation = *formed.simulation;
  const double pair_radius = simulation.find_group(formed.group)->ospace_radius_m();
  HumanSpec newcomer;
  newcomer.id = 30;
  newcomer.pose = {{4.0, 6.5}, -core::kPi / 2};
  simulation.add_human(newcomer);
  simulation.join_group(formed.group, 30);
  const GroupNavigation& group = *simulation.find_group(formed.group);
  EXPECT_EQ(group.arrangement(), Arrangement::kCircle);
  for (int k = 0; k < 600; ++k) {
    simulation.step();
  }
  // Three around a circle of radius 1.0 / (2 sin 60 deg) = 0.58 m, 1.0 m apart.
  const double radius =
      GroupNavigation::ospace_radius_for(3, GroupNavigation::default_member_spacing_m(3), 0.45);
  EXPECT_NEAR(group.ospace_radius_m(), radius, 1e-9);
  EXPECT_GT(group.ospace_radius_m(), pair_radius - 0.2);
  for (model::ObjectId id : group.members()) {
    const Eigen::Vector2d p = simulation.find_human(id)->pose().position;
    EXPECT_NEAR((p - group.centre()).norm(), radius, 0.12) << "human " << id;
  }

  const model::ObjectId leaving = group.members().front();
  simulation.leave_group(leaving);
  for (int k = 0; k < 600; ++k) {
    simulation.step();
  }
  // The leaver stepped 1.2 m back out; the two left face each other across the o-space, as an L
  // again (the arrangement they were set for).
  const Eigen::Vector2d out = simulation.find_human(leaving)->pose().position;
  EXPECT_GT((out - group.centre()).norm(), radius + 1.0);
  ASSERT_EQ(group.members().size(), 2u);
  EXPECT_EQ(group.arrangement(), Arrangement::kLShape);
  const Human& a = *simulation.find_human(group.members()[0]);
  const Human& b = *simulation.find_human(group.members()[1]);
  EXPECT_NEAR(std::abs(core::angle_difference(a.pose().theta, b.pose().theta)), core::kPi / 2,
              5.0 * kDeg);
  EXPECT_NEAR((a.pose().position - b.pose().position).norm(), 0.9, 0.1);
}

TEST(GroupArrangements, TwoLeftOfACircleStandVisAVis) {
  Formed formed = form(Arrangement::kCircle, 3, 11);
  Simulation& simulation = *formed.simulation;
  const GroupNavigation& group = *simulation.find_group(formed.group);
  simulation.leave_group(group.members()[1]);
  for (int k = 0; k < 600; ++k) {
    simulation.step();
  }
  EXPECT_EQ(group.arrangement(), Arrangement::kVisAVis);
  const Human& a = *simulation.find_human(group.members()[0]);
  const Human& b = *simulation.find_human(group.members()[1]);
  EXPECT_NEAR(std::abs(core::angle_difference(a.pose().theta, b.pose().theta)), core::kPi,
              10.0 * kDeg);
  // Closed to the pair's spacing, 0.9 m.
  EXPECT_NEAR((a.pose().position - b.pose().position).norm(), 0.9, 0.1);
}

// ARI coming up to a circle of three, facing it, is counted: the members open a fourth place
// where ARI stands and widen the o-space; ARI going away closes it.
TEST(GroupArrangements, MembersOpenAPlaceForARIApproachingAndCloseItAfter) {
  Formed formed = form(Arrangement::kCircle, 3, 13);
  Simulation& simulation = *formed.simulation;
  const GroupNavigation& group = *simulation.find_group(formed.group);
  // Where a fourth would stand, 1.0 m out from the centre, facing it, away from every member.
  double bearing = 0.0;
  double best_gap = -1.0;
  for (int k = 0; k < 72; ++k) {
    const double candidate = k * 5.0 * kDeg;
    double gap = core::kPi;
    for (model::ObjectId id : group.members()) {
      const Eigen::Vector2d d = simulation.find_human(id)->pose().position - group.centre();
      gap = std::min(gap, std::abs(core::angle_difference(std::atan2(d.y(), d.x()), candidate)));
    }
    if (gap > best_gap) {
      best_gap = gap;
      bearing = candidate;
    }
  }
  const Eigen::Vector2d outward(std::cos(bearing), std::sin(bearing));
  AriSpec ari;
  ari.pose = {group.centre() + 1.0 * outward, bearing + core::kPi};
  simulation.add_ari(ari);
  simulation.step();
  EXPECT_EQ(group.robot_joining(), ari.id);
  EXPECT_EQ(group.participant_count(), 4u);
  for (int k = 0; k < 600; ++k) {
    simulation.step();
  }
  // Members spread over the rest of the ring: none within 60 deg of ARI's bearing (four evenly
  // spaced stand 90 deg apart), and on the wider circle of four.
  const double radius_of_four =
      GroupNavigation::ospace_radius_for(4, GroupNavigation::default_member_spacing_m(4), 0.45);
  const Eigen::Vector2d robot = simulation.ari()->centre() - group.centre();
  for (model::ObjectId id : group.members()) {
    const Eigen::Vector2d d = simulation.find_human(id)->pose().position - group.centre();
    EXPECT_GT(std::abs(core::angle_difference(std::atan2(d.y(), d.x()),
                                              std::atan2(robot.y(), robot.x()))),
              60.0 * kDeg)
        << "human " << id;
    EXPECT_NEAR(d.norm(), radius_of_four, 0.15) << "human " << id;
  }
  // ARI leaves: no longer counted while it is near; the three close the circle again.
  simulation.leave_group(ari.id);
  EXPECT_EQ(group.robot_joining(), model::kNoObject);
  for (int k = 0; k < 600; ++k) {
    simulation.step();
  }
  EXPECT_EQ(group.robot_joining(), model::kNoObject);
  const double radius_of_three =
      GroupNavigation::ospace_radius_for(3, GroupNavigation::default_member_spacing_m(3), 0.45);
  for (model::ObjectId id : group.members()) {
    const Eigen::Vector2d d = simulation.find_human(id)->pose().position - group.centre();
    EXPECT_NEAR(d.norm(), radius_of_three, 0.12) << "human " << id;
  }
}

TEST(GroupArrangements, ARIPassingByOrFacingAwayIsNotCounted) {
  Formed formed = form(Arrangement::kCircle, 3, 17, 0.0, 5.0);
  Simulation& simulation = *formed.simulation;
  const GroupNavigation& group = *simulation.find_group(formed.group);
  AriSpec ari;
  // 1.8 m from the centre but heading past it (90 deg off).
  ari.pose = {group.centre() + Eigen::Vector2d(0.0, -1.8), 0.0};
  simulation.add_ari(ari);
  simulation.step();
  EXPECT_EQ(group.robot_joining(), model::kNoObject);
  // Asked to join, it is counted wherever it is.
  simulation.join_group(formed.group, ari.id);
  simulation.step();
  EXPECT_EQ(group.robot_joining(), ari.id);
}

// A third person joining a side-by-side pair turns it to face them: a circle of three. When they
// leave, the pair stands side by side again, each at a place of the row.
TEST(GroupArrangements, RowsJoinedBecomeACircleAndFormAgainWhenLeft) {
  Formed formed = form(Arrangement::kSideBySide, 2, 19);
  Simulation& simulation = *formed.simulation;
  HumanSpec newcomer;
  newcomer.id = 30;
  newcomer.pose = {{6.0, 6.0}, 0.0};
  simulation.add_human(newcomer);
  simulation.add_group_members(formed.group, {30});
  const GroupNavigation& group = *simulation.find_group(formed.group);
  EXPECT_EQ(group.arrangement(), Arrangement::kCircle);
  for (int k = 0; k < 600; ++k) {
    simulation.step();
  }
  const double radius =
      GroupNavigation::ospace_radius_for(3, GroupNavigation::default_member_spacing_m(3), 0.45);
  for (model::ObjectId id : group.members()) {
    const Eigen::Vector2d p = simulation.find_human(id)->pose().position;
    EXPECT_NEAR((p - group.centre()).norm(), radius, 0.12) << "human " << id;
  }
  simulation.leave_group(30);
  for (int k = 0; k < 600; ++k) {
    simulation.step();
  }
  EXPECT_EQ(group.arrangement(), Arrangement::kSideBySide);
  for (size_t i = 0; i < group.members().size(); ++i) {
    EXPECT_LT(
        (simulation.find_human(group.members()[i])->pose().position - group.places()[i].position)
            .norm(),
        0.1);
  }
}

TEST(GroupArrangements, BadRequestsAreRefusedWithTheirField) {
  std::unique_ptr<Simulation> simulation = test::request_world();
  EXPECT_EQ(test::refusal_text(
                [&] { simulation->set_group_arrangement(9, Arrangement::kLShape, std::nullopt); }),
            "set_group_arrangement: group_id: no group with id 9");
  EXPECT_EQ(
      test::refusal_text(
          [&] { simulation->set_group_arrangement(1, Arrangement::kLShape, std::nan("")); }),
      "set_group_arrangement: heading: expected a finite number [-1e+06, 1e+06] rad, got nan");
  EXPECT_EQ(test::refusal_text([&] { simulation->join_group(1, 77); }),
            "join_group: agent_id: no human or ARI with id 77");
  EXPECT_EQ(test::refusal_text([&] { simulation->leave_group(12); }),
            "leave_group: agent_id: expected an agent in a group, got human 12, who is in none");
  EXPECT_EQ(test::refusal_text([&] { simulation->leave_group(1); }),
            "leave_group: agent_id: expected an agent in a group, got ARI, who is in none");
  EXPECT_EQ(test::refusal_text(
                [] { requested_arrangement("create_group", "line", Arrangement::kCircle); }),
            "create_group: arrangement: expected circle, vis-a-vis, l-shape or side-by-side, got "
            "'line'");
  EXPECT_EQ(requested_arrangement("create_group", "", Arrangement::kCircle), Arrangement::kCircle);
  const std::string scene_error = test::refusal_text<core::ConfigError>([] {
    parse_group(core::YamlMap::parse(
        "{id: 1, members: [10, 11], centre: [1, 1], arrangement: triangle}", "scene.yaml"));
  });
  EXPECT_NE(scene_error.find("scene.yaml"), std::string::npos) << scene_error;
  EXPECT_NE(scene_error.find("arrangement"), std::string::npos) << scene_error;
  EXPECT_NE(scene_error.find("circle, vis-a-vis, l-shape or side-by-side"), std::string::npos)
      << scene_error;
  const std::string spread_error = test::refusal_text<core::ConfigError>([] {
    parse_group(core::YamlMap::parse(
        "{id: 1, members: [10, 11], centre: [1, 1], facing_spread: 90}", "scene.yaml"));
  });
  EXPECT_NE(spread_error.find("facing_spread"), std::string::npos) << spread_error;
  for (const char* field : {"row_facing_spread: 90", "row_spacing_spread: -0.1"}) {
    const std::string row_error = test::refusal_text<core::ConfigError>([&] {
      parse_group(core::YamlMap::parse(
          std::string("{id: 1, members: [10, 11], centre: [1, 1], ") + field + "}", "scene.yaml"));
    });
    EXPECT_NE(row_error.find(std::string(field).substr(0, std::string(field).find(':'))),
              std::string::npos)
        << row_error;
    EXPECT_NE(row_error.find("scene.yaml"), std::string::npos) << row_error;
  }
}

}  // namespace
}  // namespace ari_social_sim::world
