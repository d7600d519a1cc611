#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "ari_social_sim/core/rng.hpp"
#include "ari_social_sim/world/simulation.hpp"
#include "scene_builders.hpp"

namespace ari_social_sim::world {
namespace {

// The neighbours a brute-force scan over every human and ARI finds, sorted for comparison.
std::vector<std::pair<double, double>> brute_force(const Simulation& simulation,
                                                   const Eigen::Vector2d& point, double radius_m,
                                                   const Object* exclude) {
  std::vector<std::pair<double, double>> found;
  auto consider = [&](const Object& agent) {
    if (&agent != exclude && (agent.centre() - point).norm() < radius_m) {
      found.emplace_back(agent.centre().x(), agent.centre().y());
    }
  };
  for (const auto& human : simulation.humans()) {
    consider(*human);
  }
  if (simulation.ari() != nullptr) {
    consider(*simulation.ari());
  }
  std::sort(found.begin(), found.end());
  return found;
}

std::vector<std::pair<double, double>> from_grid(const Simulation& simulation,
                                                 const Eigen::Vector2d& point, double radius_m,
                                                 const Object* exclude) {
  std::vector<Eigen::Vector2d> centres;
  simulation.agent_centres_near(point, radius_m, exclude, centres);
  std::vector<std::pair<double, double>> found;
  for (const Eigen::Vector2d& c : centres) {
    found.emplace_back(c.x(), c.y());
  }
  std::sort(found.begin(), found.end());
  return found;
}

// Compares grid queries with a brute-force scan at 400 random points and radii (0.1 to 3 m, so
// queries span from part of one cell to many), and counts the neighbours found.
size_t expect_queries_match_brute_force(const Simulation& simulation, double side_m,
                                        core::Rng& rng) {
  size_t neighbours = 0;
  for (int query = 0; query < 400; ++query) {
    const Eigen::Vector2d point{rng.uniform(-1.0, side_m + 1.0), rng.uniform(-1.0, side_m + 1.0)};
    const double radius = rng.uniform(0.1, 3.0);
    const Object* exclude = simulation.humans()[query % simulation.humans().size()];
    const auto expected = brute_force(simulation, point, radius, exclude);
    EXPECT_EQ(from_grid(simulation, point, radius, exclude), expected)
        << "query at (" << point.x() << ", " << point.y() << "), radius " << radius;
    neighbours += expected.size();
  }
  return neighbours;
}

TEST(AgentGrid, NeighbourQueriesEqualABruteForceScanWhilePeopleMove) {
  constexpr double kSide = 12.0;
  Simulation simulation(test::square_room(kSide), SimulationConfig{0.05, 3, 0.05});
  AriSpec ari;
  ari.pose.position = {0.5 * kSide, 0.5 * kSide};
  simulation.add_ari(ari);
  core::Rng rng(11);
  const std::vector<model::ObjectId> ids = test::add_random_humans(simulation, 40, kSide, 0.4, rng);
  // Up to 0.9 m/s along each axis: at most 1.27 m/s, within a human's default max_speed.
  for (model::ObjectId id : ids) {
    simulation.set_human_velocity(id, {rng.uniform(-0.9, 0.9), rng.uniform(-0.9, 0.9)}, 0.0);
  }
  size_t neighbours = expect_queries_match_brute_force(simulation, kSide, rng);
  for (int step = 0; step < 40; ++step) {
    simulation.step();
  }
  neighbours += expect_queries_match_brute_force(simulation, kSide, rng);
  // Enough agents inside the query circles for the comparison to mean something.
  EXPECT_GT(neighbours, 1000u);
}

TEST(AgentGrid, QueriesSeeAgentsMovedRemovedOrAddedBetweenSteps) {
  Simulation simulation(test::square_room(6.0), SimulationConfig{});
  core::Rng rng(5);
  const std::vector<model::ObjectId> ids = test::add_random_humans(simulation, 6, 6.0, 0.5, rng);
  const Eigen::Vector2d corner{0.6, 0.6};
  std::vector<Eigen::Vector2d> near_corner;
  simulation.agent_centres_near(corner, 0.3, nullptr, near_corner);
  ASSERT_TRUE(near_corner.empty());

  simulation.set_pose(ids[0], core::Pose2{corner, 0.0});
  simulation.agent_centres_near(corner, 0.3, nullptr, near_corner);
  ASSERT_EQ(near_corner.size(), 1u);
  EXPECT_LT((near_corner[0] - corner).norm(), 1e-6);  // Box2D stores floats

  simulation.remove_human(ids[0]);
  simulation.agent_centres_near(corner, 0.3, nullptr, near_corner);
  EXPECT_TRUE(near_corner.empty());

  HumanSpec newcomer;
  newcomer.id = 99;
  newcomer.pose.position = {0.7, 0.6};
  simulation.add_human(newcomer);
  simulation.agent_centres_near(corner, 0.3, nullptr, near_corner);
  ASSERT_EQ(near_corner.size(), 1u);
  EXPECT_NEAR(near_corner[0].x(), 0.7, 1e-6);
}

}  // namespace
}  // namespace ari_social_sim::world
