#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <vector>

#include "ari_social_sim/model/world_file.hpp"
#include "ari_social_sim/navigation/geodesic_field.hpp"
#include "ari_social_sim/navigation/personal_space_cost.hpp"
#include "ari_social_sim/navigation/signed_distance_field.hpp"
#include "ari_social_sim/navigation/social_mpc.hpp"
#include "ari_social_sim/world/map_sensor.hpp"
#include "navigation_fixtures.hpp"

namespace {

using namespace ari_social_sim;
using namespace ari_social_sim::navigation;

const FootprintModel kFootprint = FootprintModel::covering(model::AriFootprint{}, 3);

// The hospital waiting room (12 x 9 m at 0.05 m), as world_node serves it by default.
model::OccupancyGrid waiting_room_map() {
  return world::rasterize_static_map(
      model::load_world_file(std::string(ARI_SOURCE_DIR) + "/worlds/hospital_waiting_room.yaml"),
      0.05);
}

// A joining problem in an 8 m room: ARI 3 m from a group of three it joins, a second group of
// three and two people walking across, the head keeping the group centre in view.
struct BusyProblem : test::RoomProblem {
  BusyProblem() : test::RoomProblem(8.0, test::pose(1.5, 2.0, 0.3), test::pose(4.2, 4.0, 0.4)) {
    std::vector<PersonEstimate> joined, other;
    for (int i = 0; i < 3; ++i) {
      const double a = 2.0 + 2.0 * M_PI * i / 3.0;
      joined.push_back(test::person("human" + std::to_string(10 + i), 4.8 + 0.64 * std::cos(a),
                                    4.3 + 0.64 * std::sin(a), a + M_PI));
      other.push_back(test::person("human" + std::to_string(20 + i), 2.5 + 0.64 * std::cos(a),
                                   6.0 + 0.64 * std::sin(a), a + M_PI));
    }
    for (const PersonEstimate& p : joined) {
      problem.people.push_back({p, 0.3});
    }
    for (const PersonEstimate& p : other) {
      problem.people.push_back({p, 1.0});
    }
    problem.people.push_back({test::person("human30", 3.0, 0.8, 1.57, {0.0, 1.0}), 1.0});
    problem.people.push_back({test::person("human31", 6.5, 3.0, 3.14, {-1.0, 0.0}), 1.0});
    problem.groups.push_back({estimate_group("g1", joined, 0.5), true});
    problem.groups.push_back({estimate_group("g2", other, 0.5), false});
    problem.look_at = problem.groups[0].estimate.centre;
    problem.start_linear_mps = 0.4;
  }
};

// One personal-space term over a 20-step rollout of 3 footprint circles and 8 people, with its
// gradient; items = rollouts.
void BM_PersonalSpaceCost(benchmark::State& state) {
  const BusyProblem busy;
  MpcConfig config;
  const UnicycleModel model(config.step_s, kFootprint);
  const PersonalSpaceCost term(config.weights.personal_space, config.weights.personal_space_edge,
                               kFootprint, config.personal_space,
                               config.personal_space_margin_sigmas, config.step_s);
  Eigen::VectorXd controls = Eigen::VectorXd::Constant(config.control_count(), 0.3);
  Rollout rollout;
  model.rollout(busy.problem.start, controls, rollout);
  RolloutGradient gradient;
  for (auto _ : state) {
    gradient.reset(config.horizon_steps);
    benchmark::DoNotOptimize(term.evaluate(busy.problem, rollout, controls, &gradient));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_PersonalSpaceCost);

// The whole MPC objective with its gradient (rollout, every term, reverse pass); items = calls.
void BM_TrajectoryCostWithGradient(benchmark::State& state) {
  const BusyProblem busy;
  MpcConfig config;
  const UnicycleModel model(config.step_s, kFootprint);
  TrajectoryCost cost(config, model);
  cost.set_problem(busy.problem);
  Eigen::VectorXd controls = Eigen::VectorXd::Constant(config.control_count(), 0.3);
  Eigen::VectorXd gradient;
  for (auto _ : state) {
    benchmark::DoNotOptimize(cost.evaluate(controls, &gradient));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_TrajectoryCostWithGradient);

// A cold solve (no warm start) of the busy joining problem with each solver; items = solves.
void BM_SocialMpcSolve(benchmark::State& state) {
  const BusyProblem busy;
  MpcConfig config;
  config.solver = static_cast<SolverKind>(state.range(0));
  SocialMpc mpc(config, kFootprint);
  double cost = 0.0;
  int evaluations = 0;
  for (auto _ : state) {
    mpc.reset();
    const MpcSolution solution = mpc.solve(busy.problem);
    cost = solution.cost;
    evaluations = solution.evaluations;
  }
  state.SetLabel(solver_name(config.solver));
  state.counters["cost"] = cost;
  state.counters["evaluations"] = evaluations;
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_SocialMpcSolve)
    ->ArgName("solver")
    ->Arg(0)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond);

// The signed distance field of the waiting room; items = fields.
void BM_SignedDistanceField(benchmark::State& state) {
  const model::OccupancyGrid map = waiting_room_map();
  for (auto _ : state) {
    benchmark::DoNotOptimize(signed_distance_field(map).values().data());
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_SignedDistanceField)->Unit(benchmark::kMillisecond);

// The fast-marching geodesic field across the waiting room with 6 people as cost discs (recomputed
// when the goal or the people move); items = fields.
void BM_GeodesicField(benchmark::State& state) {
  const GridField sdf = signed_distance_field(waiting_room_map());
  std::vector<CostDisc> discs;
  for (int i = 0; i < 6; ++i) {
    discs.push_back({{2.0 + 1.5 * i, 4.5}, 0.78, 6.0});
  }
  for (auto _ : state) {
    const GeodesicField field(sdf, {9.4, 2.4}, GeodesicParams{}, discs);
    benchmark::DoNotOptimize(field.field().values().data());
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_GeodesicField)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
