// Physics-only speed of ARI on Bullet: 1 kHz steps of ARI driving a circle in the waiting room
// while its head and arms follow trajectories, with and without people around. Reported as steps
// per second and as the real-time factor (sim seconds per wall second, counters "rtf").

#include <benchmark/benchmark.h>

#include <cmath>

#include "ari_social_sim/model/world_file.hpp"
#include "ari_social_sim/physics/ari_physics.hpp"

namespace ari_social_sim::physics {
namespace {

const RobotModel& ari() {
  static const RobotModel model = RobotModel::from_urdf_file(ARI_URDF);
  return model;
}

const model::WorldDescription& waiting_room() {
  static const model::WorldDescription world =
      model::load_world_file(std::string(ARI_SOURCE_DIR) + "/worlds/hospital_waiting_room.yaml");
  return world;
}

// Head and arms swinging between two poses every 2 s: every servo and limit busy.
void command_joints(AriPhysics& physics, int phase) {
  const double sign = phase % 2 == 0 ? 1.0 : -1.0;
  TrajectoryRequest head;
  head.joint_names = {"head_1_joint", "head_2_joint"};
  head.points = {{{0.8 * sign, 0.2}, {}, {}, 1.5}};
  physics.controller("head_controller").follow(head, physics.time_s(), false);
  for (const std::string side : {"left", "right"}) {
    TrajectoryRequest arm;
    arm.joint_names = {"arm_" + side + "_1_joint", "arm_" + side + "_2_joint",
                       "arm_" + side + "_3_joint", "arm_" + side + "_4_joint"};
    arm.points = {{{0.5 * sign, 0.4, 0.0, 0.8 + 0.4 * sign}, {}, {}, 1.5}};
    physics.controller("arm_" + side + "_controller").follow(arm, physics.time_s(), false);
  }
}

void BM_PhysicsStep(benchmark::State& state) {
  const int people_count = static_cast<int>(state.range(0));
  AriPhysics physics(ari(), waiting_room(), {{6.0, 3.0}, 0.0}, PhysicsConfig{});
  std::vector<PersonState> people;
  for (int i = 0; i < people_count; ++i) {
    PersonState person;
    person.id = static_cast<uint32_t>(10 + i);
    person.pose.position = {1.5 + 0.9 * (i % 10), 6.5 + 0.9 * (i / 10)};
    person.velocity_mps = {0.3 * std::cos(i), 0.3 * std::sin(i)};
    people.push_back(person);
  }
  physics.set_people(people);
  // Warm up: settle on the wheels and start moving.
  for (int i = 0; i < 500; ++i) {
    physics.command_base(0.4, 0.3);
    physics.step();
  }
  int64_t steps = 0;
  for (auto _ : state) {
    if (steps % 50 == 0) {
      physics.command_base(0.4, 0.3);  // cmd_vel at 20 Hz
    }
    if (steps % 2000 == 0) {
      command_joints(physics, static_cast<int>(steps / 2000));
      physics.set_people(people);  // world_state at the trajectory rate keeps people in place
    }
    physics.step();
    ++steps;
  }
  state.SetItemsProcessed(steps);
  state.counters["rtf"] = benchmark::Counter(static_cast<double>(steps) * physics.config().step_s,
                                             benchmark::Counter::kIsRate);
}
BENCHMARK(BM_PhysicsStep)->ArgName("people")->Arg(0)->Arg(10)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace ari_social_sim::physics

BENCHMARK_MAIN();
