// PeopleReports: each world state is drawn over its own world step, whether the physics runs
// behind the world (newer states waiting) or ahead of it (its own clock).

#include <gtest/gtest.h>

#include "ari_social_sim/physics/people_reports.hpp"

namespace ari_social_sim::physics {
namespace {

constexpr double kWorldStep_s = 0.05;
constexpr double kPhysicsStep_s = 0.005;

// One person at x = `x`: the report's mark.
std::vector<PersonState> person_at(double x) {
  PersonState person;
  person.id = 10;
  person.pose.position = {x, 0.0};
  return {person};
}

double x_of(const std::vector<PersonState>& people) {
  return people.at(0).pose.position.x();
}

TEST(PeopleReports, APhysicsBehindTheWorldDrawsEachStateOverItsOwnStep) {
  PeopleReports reports;
  // The world has published four states (0.05 .. 0.20 s) while the physics is still at 0.
  for (int k = 1; k <= 4; ++k) {
    reports.add(k * kWorldStep_s, person_at(k));
  }
  std::vector<double> drawn;  // the report in force at each physics step's end
  double in_force = -1.0;
  for (int step = 1; step * kPhysicsStep_s <= 4 * kWorldStep_s + 1e-9; ++step) {
    if (auto people = reports.take_for(step * kPhysicsStep_s)) {
      in_force = x_of(*people);
    }
    drawn.push_back(in_force);
  }
  ASSERT_EQ(drawn.size(), 40u);
  // Steps ending in (0, 0.05] draw the state of 0.05, those in (0.05, 0.10] that of 0.10, ...
  for (size_t i = 0; i < drawn.size(); ++i) {
    EXPECT_EQ(drawn[i], double(i / 10 + 1)) << "step " << i + 1;
  }
}

TEST(PeopleReports, EachReportIsHandedOutOnce) {
  PeopleReports reports;
  EXPECT_TRUE(reports.has_report_for(0.01));  // a world that never reported holds nothing up
  EXPECT_FALSE(reports.take_for(0.01));       // nothing yet
  reports.add(0.05, person_at(1.0));
  ASSERT_TRUE(reports.take_for(0.01));
  EXPECT_FALSE(reports.take_for(0.02));  // the same report, already in force
  EXPECT_FALSE(reports.take_for(0.05));
}

TEST(PeopleReports, APhysicsAheadOfTheWorldTakesTheNewestThereIs) {
  // The physics' own clock: the world's state of a time comes after the physics has passed it.
  PeopleReports reports;
  reports.add(0.05, person_at(1.0));
  reports.add(0.10, person_at(2.0));
  const auto people = reports.take_for(0.125);
  ASSERT_TRUE(people);
  EXPECT_EQ(x_of(*people), 2.0);
  EXPECT_FALSE(reports.take_for(0.13));
  reports.add(0.15, person_at(3.0));
  const auto next = reports.take_for(0.16);
  ASSERT_TRUE(next);
  EXPECT_EQ(x_of(*next), 3.0);
  EXPECT_TRUE(reports.has_report_for(0.15));
  EXPECT_FALSE(reports.has_report_for(0.16));
}

TEST(PeopleReports, AResetWorldStartsAfresh) {
  PeopleReports reports;
  reports.add(5.00, person_at(1.0));
  reports.add(5.05, person_at(2.0));
  ASSERT_TRUE(reports.take_for(5.01));
  // Reset to 0: the states from before are dropped and the new one is handed out.
  reports.add(0.05, person_at(7.0));
  EXPECT_TRUE(reports.has_report_for(0.05));
  EXPECT_FALSE(reports.has_report_for(0.1));
  const auto people = reports.take_for(0.01);
  ASSERT_TRUE(people);
  EXPECT_EQ(x_of(*people), 7.0);
}

TEST(PeopleReports, KeepsAtMostItsCapacity) {
  PeopleReports reports;
  for (size_t k = 1; k <= PeopleReports::kCapacity + 5; ++k) {
    reports.add(k * kWorldStep_s, person_at(double(k)));
  }
  // The five oldest are gone: the first left is the sixth.
  const auto people = reports.take_for(0.0);
  ASSERT_TRUE(people);
  EXPECT_EQ(x_of(*people), 6.0);
}

}  // namespace
}  // namespace ari_social_sim::physics
