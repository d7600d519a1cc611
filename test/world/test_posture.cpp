#include <gtest/gtest.h>

#include <cmath>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/world/posture.hpp"
#include "ari_social_sim/world/simulation.hpp"
#include "ari_social_sim/world/world_snapshot.hpp"
#include "scene_builders.hpp"

namespace ari_social_sim::world {
namespace {

constexpr double kStepS = 0.05;

// square_room(6) with one chair, 0.45 m square, centred at (1, 3).
std::unique_ptr<Simulation> room_with_a_chair() {
  model::WorldDescription world = test::square_room(6.0);
  model::StaticObject chair;
  chair.id = 2001;
  chair.name = "chair";
  chair.type = model::ShapeType::kBox;
  chair.pose.position = {1.0, 3.0};
  chair.size = {0.45, 0.45};
  world.objects.push_back(chair);
  return std::make_unique<Simulation>(world, SimulationConfig{kStepS, 1, 0.05});
}

HumanSpec person(model::ObjectId id, double x, double y, double theta,
                 Posture posture = Posture::kStanding) {
  HumanSpec spec;
  spec.id = id;
  spec.pose = {{x, y}, theta};
  spec.posture = posture;
  return spec;
}

int steps_of(double seconds) {
  return static_cast<int>(std::lround(seconds / kStepS));
}

TEST(PostureState, AChangeMovesTheSeatToFeetDistanceInTheChangeTime) {
  PostureState state{Posture::kSitting, 1.0};
  EXPECT_DOUBLE_EQ(state.seated_fraction(), 1.0);
  state.change_to(Posture::kStanding);
  double travelled_m = 0.0;
  int steps = 0;
  while (state.is_changing()) {
    travelled_m += state.advance(kStepS) * kStepS;
    ++steps;
  }
  // 1.7 s / 0.05 s = 34 steps, 0.45 m forward.
  EXPECT_EQ(steps, 34);
  EXPECT_NEAR(travelled_m, kSeatToFeetM, 1e-12);
  EXPECT_TRUE(state.is_standing());
}

TEST(PostureState, TheApparentPostureTurnsHalfwayThroughAChange) {
  // Standing up over 34 steps of 0.05 s: seated fraction 1 - k/34, over 0.5 until step 17.
  PostureState state{Posture::kSitting, 1.0};
  EXPECT_EQ(state.apparent(), Posture::kSitting);
  state.change_to(Posture::kStanding);
  for (int k = 0; k < 16; ++k) {
    state.advance(kStepS);
  }
  EXPECT_EQ(state.apparent(), Posture::kSitting);  // 16/34 up: seated fraction 0.53
  state.advance(kStepS);
  state.advance(kStepS);
  EXPECT_EQ(state.apparent(), Posture::kStanding);  // 18/34 up: 0.47
  EXPECT_EQ((PostureState{Posture::kStanding, 1.0}.apparent()), Posture::kStanding);
}

TEST(PostureState, AChangeTurnedBackMidwayTakesOnlyWhatItHadDone) {
  PostureState state{Posture::kSitting, 1.0};
  state.change_to(Posture::kStanding);
  for (int i = 0; i < 10; ++i) {
    state.advance(kStepS);
  }
  state.change_to(Posture::kSitting);
  // 10 steps up, so 10 steps down: 10 / 34 of the change is left to undo.
  EXPECT_NEAR(state.progress, 1.0 - 10.0 / 34.0, 1e-12);
  EXPECT_NEAR(state.seated_fraction(), 1.0 - 10.0 / 34.0, 1e-12);
  double travelled_m = 0.0;
  while (state.is_changing()) {
    travelled_m += state.advance(kStepS) * kStepS;
  }
  EXPECT_NEAR(travelled_m, -10.0 / 34.0 * kSeatToFeetM, 1e-12);
}

TEST(Posture, ASeatedPersonStaysOnTheSeatWhileOthersWalkPastAndIntoThem) {
  auto simulation = room_with_a_chair();
  const Human& seated = simulation->add_human(person(10, 1.0, 3.0, 0.0, Posture::kSitting));
  simulation->add_human(person(11, 2.0, 0.8, M_PI / 2));
  simulation->add_human(person(12, 4.0, 3.0, M_PI));
  simulation->set_human_goal(11, {{2.0, 5.5}, M_PI / 2});
  // Walks straight at the seated person's chest at 0.8 m/s, on and on.
  simulation->set_human_velocity(12, {-0.8, 0.0}, 0.0);
  double worst_m = 0.0;
  for (int i = 0; i < steps_of(60.0); ++i) {
    simulation->step();
    worst_m = std::max(worst_m, (seated.pose().position - Eigen::Vector2d(1.0, 3.0)).norm());
    if (i == steps_of(30.0)) {
      simulation->set_human_goal(11, {{2.0, 0.8}, -M_PI / 2});
    }
  }
  EXPECT_LT(worst_m, 0.003);
  EXPECT_DOUBLE_EQ(seated.pose().theta, 0.0);
  EXPECT_EQ(seated.posture().posture, Posture::kSitting);
  // The walker was stopped at the chair's front (x 1.225) plus its radius 0.2, within Box2D's slop.
  EXPECT_NEAR(simulation->find_human(12)->pose().position.x(), 1.425, 0.01);
  EXPECT_EQ(simulation->diagnostics().clamped_commands, 0u);
}

TEST(Posture, AGoalStandsASeatedPersonUpFirstThenTheyWalkThere) {
  auto simulation = room_with_a_chair();
  const Human& human = simulation->add_human(person(10, 1.0, 3.0, 0.0, Posture::kSitting));
  simulation->set_human_goal(10, {{4.5, 3.0}, 0.0});
  // Standing up: 34 steps of 1.7 s at 0.45 m / 1.7 s forward, the heading kept.
  for (int i = 0; i < steps_of(kPostureChangeS) - 1; ++i) {
    simulation->step();
    ASSERT_TRUE(human.posture().is_changing()) << "step " << i;
    ASSERT_NEAR(human.velocity().x(), kSeatToFeetM / kPostureChangeS, 1e-4);
  }
  simulation->step();
  EXPECT_TRUE(human.posture().is_standing());
  EXPECT_NEAR(human.pose().position.x(), 1.0 + kSeatToFeetM, 1e-3);
  EXPECT_NEAR(human.pose().position.y(), 3.0, 1e-3);
  // Then the walk: 3.05 m at about 1 m/s.
  for (int i = 0; i < steps_of(8.0); ++i) {
    simulation->step();
  }
  EXPECT_NEAR(human.pose().position.x(), 4.5, 0.1);
  EXPECT_EQ(WorldSnapshot::of(*simulation).humans[0].posture.posture, Posture::kStanding);
}

TEST(Posture, SittingDownGoesBackOntoTheSeatAndEndsAWalk) {
  auto simulation = room_with_a_chair();
  const Human& human = simulation->add_human(person(10, 1.45, 3.0, 0.0));
  simulation->set_human_velocity(10, {0.5, 0.0}, 0.0);
  simulation->set_human_posture(10, Posture::kSitting);
  EXPECT_EQ(human.motion_mode(), MotionMode::kIdle);
  for (int i = 0; i < steps_of(kPostureChangeS); ++i) {
    simulation->step();
    ASSERT_NEAR(WorldSnapshot::of(*simulation).humans[0].posture.seated_fraction(), (i + 1) / 34.0,
                1e-9);
  }
  EXPECT_NEAR(human.pose().position.x(), 1.0, 1e-3);
  EXPECT_NEAR(human.pose().position.y(), 3.0, 1e-3);
  EXPECT_THROW(simulation->set_human_posture(99, Posture::kStanding), core::RequestError);
}

TEST(Posture, ASeatedSpawnMayOverlapFurnitureButNotWallsOrPeople) {
  auto simulation = room_with_a_chair();
  EXPECT_THROW(simulation->add_human(person(10, 1.0, 3.0, 0.0)), core::RequestError);
  EXPECT_NO_THROW(simulation->add_human(person(11, 1.0, 3.0, 0.0, Posture::kSitting)));
  EXPECT_THROW(simulation->add_human(person(12, 1.2, 3.0, 0.0, Posture::kSitting)),
               core::RequestError);
  EXPECT_THROW(simulation->add_human(person(13, 0.1, 1.0, 0.0, Posture::kSitting)),
               core::RequestError);
}

}  // namespace
}  // namespace ari_social_sim::world
