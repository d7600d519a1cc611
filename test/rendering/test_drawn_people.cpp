// DrawnPeople: the figures posed where ari_physics_node drew them, one world step ahead of the
// world state an image falls before.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/core/yaml_map.hpp"
#include "ari_social_sim/model/world_file.hpp"
#include "ari_social_sim/physics/ari_physics.hpp"
#include "ari_social_sim/physics/people_reports.hpp"
#include "ari_social_sim/rendering/drawn_people.hpp"

namespace ari_social_sim::rendering {
namespace {

world::HumanSnapshot walker(model::ObjectId id, const Eigen::Vector2d& position,
                            const Eigen::Vector2d& velocity_mps, double angular_velocity_rps) {
  world::HumanSnapshot human;
  human.id = id;
  human.age_years = 30.0;
  human.pose = {position, 0.0};
  human.velocity_mps = velocity_mps;
  human.angular_velocity_rps = angular_velocity_rps;
  return human;
}

const PosedPerson& only(const std::vector<PosedPerson>& posed) {
  EXPECT_EQ(posed.size(), 1u);
  return posed.front();
}

TEST(DrawnPeople, OneStateIsWalkedOnFromADefaultStepBeforeIt) {
  DrawnPeople drawn(1);
  EXPECT_TRUE(drawn.empty());
  drawn.add_state(1.0, {walker(4, {2.0, 0.5}, {1.0, 0.0}, 0.0)});
  EXPECT_FALSE(drawn.empty());
  // Received at 1.0 - 0.05 s: at 1.05 s the figure has walked 0.1 s at 1 m/s.
  const PosedPerson& person = only(drawn.pose_at(1.05));
  EXPECT_EQ(person.id, 4u);
  EXPECT_NEAR(person.pose.body.position.x(), 2.1, 1e-12);
  EXPECT_NEAR(person.pose.body.position.y(), 0.5, 1e-12);
}

TEST(DrawnPeople, AnImageShowsTheNextStateWalkedOnFromThePreviousStamp) {
  DrawnPeople drawn(1);
  drawn.add_state(1.0, {walker(4, {2.0, 0.0}, {0.0, 0.0}, 0.0)});
  drawn.add_state(1.05, {walker(4, {3.0, 0.0}, {0.0, -2.0}, 0.5)});
  // An image at 1.02 s falls before the state of 1.05 s, received at 1.0 s: 0.02 s ahead of it.
  const PosedPerson& between = only(drawn.pose_at(1.02));
  EXPECT_NEAR(between.pose.body.position.x(), 3.0, 1e-12);
  EXPECT_NEAR(between.pose.body.position.y(), -0.04, 1e-12);
  EXPECT_NEAR(between.pose.body.theta, 0.01, 1e-12);
  // An image at a state's own stamp is that state one step (0.05 s) on.
  const PosedPerson& at_state = only(drawn.pose_at(1.05));
  EXPECT_NEAR(at_state.pose.body.position.y(), -0.1, 1e-12);
  // Later than the last state: the last, walked on from the stamp before it.
  const PosedPerson& later = only(drawn.pose_at(1.2));
  EXPECT_NEAR(later.pose.body.position.y(), -0.4, 1e-12);
}

// The gait phase is the walked distance, walked on as the position is, in strides of 0.8 of
// stature: whoever poses the figure from the same state (the physics, ~crops) poses it alike.
TEST(DrawnPeople, TheGaitIsTheWalkedDistanceWalkedOn) {
  DrawnPeople drawn(1);
  world::HumanSnapshot human = walker(4, {2.0, 0.0}, {0.0, 1.0}, 0.0);
  human.walked_m = 3.0;
  drawn.add_state(1.0, {human});
  const PosedPerson& person = only(drawn.pose_at(1.05));
  const double stride = 0.8 * person.figure->appearance().height_m;
  EXPECT_NEAR(person.pose.gait_phase_rad, 2.0 * M_PI * std::fmod(3.1, stride) / stride, 1e-9);
  // Posed again later from an earlier image: the same phase (no state of its own in the figures).
  drawn.pose_at(1.2);
  EXPECT_NEAR(only(drawn.pose_at(1.05)).pose.gait_phase_rad,
              2.0 * M_PI * std::fmod(3.1, stride) / stride, 1e-9);
}

TEST(DrawnPeople, AnImageWaitsForAStateStampedNoEarlier) {
  DrawnPeople drawn(1);
  EXPECT_FALSE(drawn.has_state_for(1.0));
  drawn.add_state(1.0, {walker(4, {2.0, 0.0}, {1.0, 0.0}, 0.0)});
  EXPECT_TRUE(drawn.has_state_for(0.98));
  EXPECT_TRUE(drawn.has_state_for(1.0));
  EXPECT_FALSE(drawn.has_state_for(1.02));  // drawn from the state of 1.05, not here yet
}

// The whole chain as ari_physics_node and hri_perception_node run it: a walker whose speed
// changes every world step, reported to the physics through PeopleReports and stepped at 1 kHz,
// drawn every 0.1 s from the physics' people; the same states posed by DrawnPeople at the frames'
// stamps. Both pose the same person: within a centimetre, at the same gait phase.
TEST(DrawnPeople, PosesThePeopleAsThePhysicsDrawsThem) {
  const physics::RobotModel ari = physics::RobotModel::from_urdf_file(ARI_URDF);
  const model::WorldDescription floor = model::parse_world(core::YamlMap::parse(
      "name: floor\norigin: [-5, -5]\nsize: [20, 20]\nobjects: []\n", "inline world"));
  physics::AriPhysics physics(ari, floor, {{0.0, 0.0}, 0.0}, physics::PhysicsConfig{});
  physics::PeopleReports reports;
  DrawnPeople drawn(1);
  PeopleFigures drawn_by_physics(1);
  constexpr double kWorldStep_s = 0.05;
  world::HumanSnapshot human = walker(4, {3.0, -2.0}, {0.0, 1.0}, 0.0);
  double worst_position_m = 0.0, worst_phase_rad = 0.0;
  int frames = 0;
  for (int k = 1; k <= 60; ++k) {
    // The world: the speed swings between 0.7 and 1.3 m/s.
    human.velocity_mps = {0.0, 1.0 + 0.3 * std::sin(0.3 * k)};
    human.pose.position += kWorldStep_s * human.velocity_mps;
    human.walked_m += kWorldStep_s * human.velocity_mps.norm();
    const double stamp_s = k * kWorldStep_s;
    physics::PersonState reported;
    reported.id = human.id;
    reported.pose = human.pose;
    reported.velocity_mps = human.velocity_mps;
    reported.age_years = human.age_years;
    reported.walked_m = human.walked_m;
    reports.add(stamp_s, {reported});
    drawn.add_state(stamp_s, {human});
    // The physics steps to the state's stamp, drawing a frame every 0.1 s.
    const double step_s = physics.config().step_s;
    while (physics.time_s() + 0.5 * step_s < stamp_s) {
      if (auto people = reports.take_for(physics.time_s() + step_s)) {
        physics.set_people(*people);
      }
      physics.step();
      const long step = std::lround(physics.time_s() / step_s);
      if (k < 4 || step % std::lround(0.1 / step_s) != 0) {
        continue;  // the first steps: the physics places the person
      }
      std::vector<FigureInput> inputs;
      for (const physics::PersonState& person : physics.people_states()) {
        inputs.push_back(figure_input_of(person));
      }
      drawn_by_physics.update(physics.time_s(), inputs);
      const PosedPerson& truth = only(drawn_by_physics.posed());
      const PosedPerson& ours = only(drawn.pose_at(physics.time_s()));
      worst_position_m =
          std::max(worst_position_m, (ours.pose.body.position - truth.pose.body.position).norm());
      worst_phase_rad = std::max(
          worst_phase_rad,
          std::abs(core::angle_difference(ours.pose.gait_phase_rad, truth.pose.gait_phase_rad)));
      ++frames;
    }
  }
  std::printf("%d frames: at most %.2f mm and %.4f rad of gait phase apart\n", frames,
              1000 * worst_position_m, worst_phase_rad);
  EXPECT_GE(frames, 25);
  // The physics glides to each report within 0.1 s rather than jump: with the speed changing by
  // up to 1.8 m/s^2 it trails the reported walk by millimetres (5.9 measured).
  EXPECT_LT(worst_position_m, 0.01);
  EXPECT_LT(worst_phase_rad, 1e-6);
}

TEST(DrawnPeople, AnImageBeforeEveryStateIsNotWalkedBackwards) {
  DrawnPeople drawn(1);
  drawn.add_state(1.0, {walker(4, {2.0, 0.0}, {1.0, 0.0}, 0.0)});
  const PosedPerson& person = only(drawn.pose_at(0.5));
  EXPECT_NEAR(person.pose.body.position.x(), 2.0, 1e-12);
}

TEST(DrawnPeople, AnEarlierStateStartsTheHistoryAfresh) {
  DrawnPeople drawn(1);
  drawn.add_state(5.0, {walker(4, {9.0, 0.0}, {0.0, 0.0}, 0.0)});
  drawn.add_state(5.05, {walker(4, {9.0, 0.0}, {0.0, 0.0}, 0.0)});
  drawn.add_state(1.0, {walker(7, {2.0, 0.0}, {1.0, 0.0}, 0.0)});
  // Only the reset's state is left: the one before it (5.05 s) would put it 4 s back in time.
  const PosedPerson& person = only(drawn.pose_at(1.05));
  EXPECT_EQ(person.id, 7u);
  EXPECT_NEAR(person.pose.body.position.x(), 2.1, 1e-12);
}

TEST(DrawnPeople, KeepsTheLastStates) {
  DrawnPeople drawn(1);
  for (size_t k = 0; k < DrawnPeople::kHistory + 10; ++k) {
    const double x = static_cast<double>(k);
    drawn.add_state(0.05 * x, {walker(4, {x, 0.0}, {1.0, 0.0}, 0.0)});
  }
  // An image at time 0 falls before the oldest state kept (the 10th), walked on not at all.
  const PosedPerson& person = only(drawn.pose_at(0.0));
  EXPECT_NEAR(person.pose.body.position.x(), 10.0, 1e-12);
}

}  // namespace
}  // namespace ari_social_sim::rendering
