#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <new>
#include <string>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/perception/gcff.hpp"

// Counts heap allocations while `g_count_allocations` is set (Drake's limit_malloc idea, minimal):
// the replacement operator new serves the whole test binary, counting only inside a window.
namespace {
bool g_count_allocations = false;
int g_allocations = 0;
}  // namespace

void* operator new(std::size_t size) {
  if (g_count_allocations) {
    ++g_allocations;
  }
  if (void* memory = std::malloc(size == 0 ? 1 : size)) {
    return memory;
  }
  throw std::bad_alloc();
}
// Kept out of line: once inlined, GCC sees free() on memory from operator new and warns
// (-Wmismatched-new-delete) although both are ours.
__attribute__((noinline)) void operator delete(void* memory) noexcept {
  std::free(memory);
}
__attribute__((noinline)) void operator delete(void* memory, std::size_t) noexcept {
  std::free(memory);
}

namespace ari_social_sim::perception {
namespace {

using core::kPi;

// Scenes in metres with the simulator's typical parameters: stride 0.6 m, mdl 0.8 m^2
// (sqrt(mdl) = 0.89 m).
GcffParams metric_params() {
  GcffParams params;
  params.stride = 0.6;
  params.mdl = 0.8;
  return params;
}

GcffPerson person(const std::string& id, double x, double y, double theta) {
  return {id, x, y, theta};
}

TEST(GcffParams, DefaultsValidate) {
  EXPECT_NO_THROW(GcffParams{}.validate());
}

TEST(GcffParams, EachBadFieldIsNamed) {
  const auto expect_error = [](GcffParams params, const std::string& fragment) {
    try {
      params.validate();
      FAIL() << "no ConfigError for " << fragment;
    } catch (const core::ConfigError& e) {
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("> 0"), std::string::npos) << e.what();
    }
  };
  GcffParams params;
  params.stride = 0.0;
  expect_error(params, "stride");
  params = GcffParams{};
  params.stride = std::nan("");
  expect_error(params, "stride");
  params = GcffParams{};
  params.mdl = -1.0;
  expect_error(params, "mdl");
  params.mdl = INFINITY;
  expect_error(params, "mdl");
  params.mdl = -1.0;
  EXPECT_THROW(GcffDetector{params}, core::ConfigError);
}

TEST(GcffCandidateCentre, LiesStrideAheadOfThePerson) {
  // (1, 2) facing +y, stride 0.5: (1, 2.5).
  const Eigen::Vector2d centre = gcff_candidate_centre(person("a", 1.0, 2.0, kPi / 2), 0.5);
  EXPECT_NEAR(centre.x(), 1.0, 1e-12);
  EXPECT_NEAR(centre.y(), 2.5, 1e-12);
}

// A (0,0) facing +x and B (1.2,0) facing -x share the centre (0.6,0); C (2,0) faces -x from
// behind B, its candidate centre (1.4,0).
class GcffUnaryCosts : public ::testing::Test {
 protected:
  std::vector<Eigen::Vector2d> positions{{0.0, 0.0}, {1.2, 0.0}, {2.0, 0.0}};
  std::vector<Eigen::Vector2d> centres{{0.6, 0.0}, {0.6, 0.0}, {1.4, 0.0}};
  std::vector<Eigen::Vector2d> hypotheses{{0.6, 0.0}, {1.4, 0.0}};
  std::vector<double> costs;
};

TEST_F(GcffUnaryCosts, MatchHandComputedValues) {
  gcff_unary_costs(positions, centres, hypotheses, 0.8, costs);
  ASSERT_EQ(costs.size(), 6u);
  // Hypothesis 0 at (0.6,0): every candidate centre within sqrt(0.8) (C: 0.8^2 = 0.64 < 0.8).
  // Seen from it A is at 0.6 m (direction -x), B at 0.6 m (+x), C at 1.4 m (+x): C stands behind
  // B, cos = 1, so C pays 100^(1 * 1.4 / 0.6) = 10^(14/3); A and B face no one in front.
  EXPECT_NEAR(costs[0 * 2 + 0], 0.0, 1e-12);
  EXPECT_NEAR(costs[1 * 2 + 0], 0.0, 1e-12);
  EXPECT_NEAR(costs[2 * 2 + 0], 0.64 + std::pow(10.0, 14.0 / 3.0), 1e-6);
  // Hypothesis 1 at (1.4,0): A at 1.4 m (-x) behind B at 0.2 m (-x): 100^(1.4 / 0.2) = 1e14,
  // capped at 1e12. B (0.2 m) and C (0.6 m, +x) are in front of nobody.
  EXPECT_DOUBLE_EQ(costs[0 * 2 + 1], 0.64 + kGcffMaxVisibilityPenalty);
  EXPECT_NEAR(costs[1 * 2 + 1], 0.64, 1e-12);
  EXPECT_NEAR(costs[2 * 2 + 1], 0.0, 1e-12);
}

TEST_F(GcffUnaryCosts, OnlyNeighbourhoodOfTheHypothesisCountsForVisibility) {
  // With mdl 0.5, C's candidate centre (0.64 from hypothesis 0) is outside M_0: no penalty.
  gcff_unary_costs(positions, centres, hypotheses, 0.5, costs);
  EXPECT_NEAR(costs[2 * 2 + 0], 0.64, 1e-12);
}

TEST_F(GcffUnaryCosts, PenaltiesAccumulateOverPeopleInFront) {
  // D at (3,0) stands behind both B (0.6 m) and C (1.4 m) as seen from hypothesis 0 (2.4 m); its
  // candidate centre is put at (1.4,0), 0.8 m from hypothesis 0, inside M_0 for mdl 1.
  positions.push_back({3.0, 0.0});
  centres.push_back({1.4, 0.0});
  gcff_unary_costs(positions, centres, hypotheses, 1.0, costs);
  // u(D,0) = 0.8^2 + 100^(2.4/0.6) + 100^(2.4/1.4) = 0.64 + 1e8 + 10^(24/7).
  const double expected = 0.64 + 1e8 + std::pow(10.0, 2.0 * 2.4 / 1.4);
  EXPECT_NEAR(costs[3 * 2 + 0], expected, 1e-6 * expected);
}

TEST(GcffDetector, NoPeopleGiveNoGroups) {
  GcffDetector detector(metric_params());
  const GcffResult result = detector.detect({});
  EXPECT_TRUE(result.labels.empty());
  EXPECT_TRUE(result.groups.empty());
  EXPECT_EQ(result.iterations, 0);
}

TEST(GcffDetector, ALonePersonIsNotAGroup) {
  GcffDetector detector(metric_params());
  const GcffResult result = detector.detect({person("a", 1.0, 1.0, 0.3)});
  ASSERT_EQ(result.labels.size(), 1u);
  EXPECT_EQ(result.labels[0], 0);
  EXPECT_TRUE(result.groups.empty());
}

TEST(GcffDetector, TwoPeopleFaceToFaceFormAGroup) {
  // 1.2 m apart facing each other: both candidate centres at (0.6, 0).
  GcffDetector detector(metric_params());
  const GcffResult result =
      detector.detect({person("a", 0.0, 0.0, 0.0), person("b", 1.2, 0.0, kPi)});
  ASSERT_EQ(result.groups.size(), 1u);
  EXPECT_EQ(result.groups[0].members, (std::vector<size_t>{0, 1}));
  EXPECT_NEAR(result.groups[0].centre.x(), 0.6, 1e-9);
  EXPECT_NEAR(result.groups[0].centre.y(), 0.0, 1e-9);
  EXPECT_EQ(result.labels[0], result.labels[1]);
}

TEST(GcffDetector, TwoPeopleBackToBackStayApart) {
  // 0.6 m apart, back to back: candidate centres (-0.6,0) and (1.2,0), 1.8 m apart. Sharing
  // the mean centre costs 2 * 0.9^2 + 0.8 = 2.42 > two labels 2 * 0.8 = 1.6.
  GcffDetector detector(metric_params());
  const GcffResult result =
      detector.detect({person("a", 0.0, 0.0, kPi), person("b", 0.6, 0.0, 0.0)});
  EXPECT_TRUE(result.groups.empty());
  ASSERT_EQ(result.labels.size(), 2u);
  EXPECT_NE(result.labels[0], result.labels[1]);
}

TEST(GcffDetector, CircleOfFourFacingTheCentreIsOneGroupAroundIt) {
  // Four people 0.7 m from (2,-1), facing it: candidate centres 0.1 m from it, symmetric, so
  // their mean is (2,-1).
  const Eigen::Vector2d centre(2.0, -1.0);
  std::vector<GcffPerson> persons;
  for (int k = 0; k < 4; ++k) {
    const double bearing = 0.3 + k * kPi / 2;
    persons.push_back(person(std::to_string(k), centre.x() + 0.7 * std::cos(bearing),
                             centre.y() + 0.7 * std::sin(bearing), bearing + kPi));
  }
  GcffDetector detector(metric_params());
  const GcffResult result = detector.detect(persons);
  ASSERT_EQ(result.groups.size(), 1u);
  EXPECT_EQ(result.groups[0].members, (std::vector<size_t>{0, 1, 2, 3}));
  EXPECT_NEAR(result.groups[0].centre.x(), 2.0, 1e-9);
  EXPECT_NEAR(result.groups[0].centre.y(), -1.0, 1e-9);
}

TEST(GcffDetector, PersonBehindAGroupMemberIsExcludedByVisibility) {
  // Control: A and C alone, 2 m apart facing each other. Candidate centres 0.8 m apart: sharing
  // (1,0) costs 2 * 0.4^2 + 0.8 = 1.12 < two labels 1.6, so they form a group.
  GcffDetector detector(metric_params());
  const GcffResult pair = detector.detect({person("a", 0.0, 0.0, 0.0), person("c", 2.0, 0.0, kPi)});
  ASSERT_EQ(pair.groups.size(), 1u);

  // With B facing A at (1.2,0), C (still facing A) sees the o-space (0.6,0) over B's shoulder:
  // joining would cost 0.64 + 100^(1.4/0.6) (see GcffUnaryCosts), far above standing alone.
  const GcffResult result = detector.detect(
      {person("a", 0.0, 0.0, 0.0), person("b", 1.2, 0.0, kPi), person("c", 2.0, 0.0, kPi)});
  ASSERT_EQ(result.groups.size(), 1u);
  EXPECT_EQ(result.groups[0].members, (std::vector<size_t>{0, 1}));
  EXPECT_NE(result.labels[2], result.labels[0]);
}

TEST(GcffDetector, TwoSeparateConversations) {
  // Two face-to-face pairs 5 m apart, listed interleaved.
  GcffDetector detector(metric_params());
  const GcffResult result =
      detector.detect({person("a", 0.0, 0.0, 0.0), person("c", 5.0, 0.0, kPi / 2),
                       person("b", 1.2, 0.0, kPi), person("d", 5.0, 1.2, -kPi / 2)});
  ASSERT_EQ(result.groups.size(), 2u);
  EXPECT_EQ(result.groups[0].members, (std::vector<size_t>{0, 2}));
  EXPECT_EQ(result.groups[1].members, (std::vector<size_t>{1, 3}));
  EXPECT_NEAR(result.groups[1].centre.x(), 5.0, 1e-9);
  EXPECT_NEAR(result.groups[1].centre.y(), 0.6, 1e-9);
}

TEST(GcffDetector, ReusedDetectorAndResultMatchFreshOnes) {
  const std::vector<GcffPerson> big = {
      person("a", 0.0, 0.0, 0.0), person("b", 1.2, 0.0, kPi), person("c", 0.6, 0.6, -kPi / 2),
      person("d", 5.0, 0.0, kPi / 2), person("e", 5.0, 1.2, -kPi / 2)};
  const std::vector<GcffPerson> small = {person("x", 0.0, 0.0, kPi), person("y", 0.6, 0.0, 0.0)};
  GcffDetector reused(metric_params());
  GcffResult result;
  reused.detect(big, result);
  reused.detect(small, result);
  EXPECT_TRUE(result.groups.empty());
  reused.detect(big, result);
  const GcffResult fresh = GcffDetector(metric_params()).detect(big);
  EXPECT_EQ(result.labels, fresh.labels);
  ASSERT_EQ(result.groups.size(), 2u);
  ASSERT_EQ(fresh.groups.size(), 2u);
  for (size_t g = 0; g < 2; ++g) {
    EXPECT_EQ(result.groups[g].members, fresh.groups[g].members);
    EXPECT_EQ(result.groups[g].centre, fresh.groups[g].centre);
  }
  EXPECT_EQ(result.groups[0].members, (std::vector<size_t>{0, 1, 2}));
}

TEST(GcffDetector, WarmDetectionsDoNotAllocate) {
  // Twelve people in four triangles; after a first call has sized the buffers, detecting the same
  // frame again (as a node does at each tick) touches the heap zero times.
  std::vector<GcffPerson> persons;
  for (int g = 0; g < 4; ++g) {
    for (int k = 0; k < 3; ++k) {
      const double bearing = 2.0 * kPi * k / 3.0;
      persons.push_back(person(std::to_string(3 * g + k), 4.0 * g + 0.7 * std::cos(bearing),
                               0.7 * std::sin(bearing), bearing + kPi));
    }
  }
  GcffDetector detector(metric_params());
  GcffResult result;
  detector.detect(persons, result);
  ASSERT_EQ(result.groups.size(), 4u);
  g_allocations = 0;
  g_count_allocations = true;
  const GcffResult copy = detector.detect(persons);  // the by-value overload does allocate
  const int counted = g_allocations;
  g_allocations = 0;
  for (int i = 0; i < 100; ++i) {
    detector.detect(persons, result);
  }
  g_count_allocations = false;
  EXPECT_GT(counted, 0);
  EXPECT_EQ(g_allocations, 0);
  EXPECT_EQ(result.groups.size(), copy.groups.size());
}

}  // namespace
}  // namespace ari_social_sim::perception
