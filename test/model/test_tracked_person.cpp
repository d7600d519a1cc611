// Which tracked persons stand where: each at their body, those without a placed body left out.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>

#include "ari_social_sim/model/tracked_person.hpp"

namespace ari_social_sim::model {
namespace {

TEST(PlaceAtBodiesTest, EachPersonStandsAtTheirBodyInTheOrderGiven) {
  const std::map<std::string, BodyPlacement> bodies = {
      {"b1", {12.5, {{1.0, 2.0}, 0.5}}},
      {"b2", {12.45, {{-3.0, 4.0}, -2.0}}},
  };
  std::vector<std::string> asked;
  const std::vector<PlacedPerson> placed =
      place_at_bodies({{"p2", "b2"}, {"p1", "b1"}},
                      [&](const std::string& body_id) -> std::optional<BodyPlacement> {
                        asked.push_back(body_id);
                        return bodies.at(body_id);
                      });
  ASSERT_EQ(placed.size(), 2u);
  EXPECT_EQ(placed[0].person_id, "p2");
  EXPECT_DOUBLE_EQ(placed[0].stamp_s, 12.45);
  EXPECT_DOUBLE_EQ(placed[0].pose.position.x(), -3.0);
  EXPECT_DOUBLE_EQ(placed[0].pose.position.y(), 4.0);
  EXPECT_DOUBLE_EQ(placed[0].pose.theta, -2.0);
  EXPECT_EQ(placed[1].person_id, "p1");
  EXPECT_DOUBLE_EQ(placed[1].stamp_s, 12.5);
  EXPECT_DOUBLE_EQ(placed[1].pose.position.x(), 1.0);
  EXPECT_DOUBLE_EQ(placed[1].pose.theta, 0.5);
  EXPECT_EQ(asked, (std::vector<std::string>{"b2", "b1"}));
}

TEST(PlaceAtBodiesTest, PersonsWithoutABodyOrWhoseBodyCannotBePlacedAreLeftOut) {
  std::vector<std::string> asked;
  const std::vector<PlacedPerson> placed =
      place_at_bodies({{"heard", ""}, {"gone", "b7"}, {"seen", "b8"}},
                      [&](const std::string& body_id) -> std::optional<BodyPlacement> {
                        asked.push_back(body_id);
                        if (body_id == "b8") {
                          return BodyPlacement{3.0, {{0.25, -0.75}, 1.0}};
                        }
                        return std::nullopt;
                      });
  ASSERT_EQ(placed.size(), 1u);
  EXPECT_EQ(placed[0].person_id, "seen");
  EXPECT_DOUBLE_EQ(placed[0].pose.position.x(), 0.25);
  EXPECT_DOUBLE_EQ(placed[0].pose.position.y(), -0.75);
  // The person without a body is not even looked up.
  EXPECT_EQ(asked, (std::vector<std::string>{"b7", "b8"}));
}

TEST(TransformProblemTest, RefusesTranslationsBeyondTheMapAndDegenerateRotations) {
  const double unit[4] = {0.0, 0.0, 0.0, 1.0};
  EXPECT_EQ(transform_problem({1.0, -2.0, 0.5}, unit), "");
  EXPECT_EQ(transform_problem({1e300, 0.0, 0.0}, unit),
            "translation x = 1e+300, expected within +-10000 m");
  EXPECT_NE(transform_problem({0.0, std::numeric_limits<double>::infinity(), 0.0}, unit), "");
  EXPECT_NE(transform_problem({0.0, 0.0, std::nan("")}, unit), "");
  EXPECT_NE(transform_problem({0.0, 0.0, 0.0}, {0.0, 0.0, 0.0, 0.0}), "");
  EXPECT_NE(transform_problem({0.0, 0.0, 0.0}, {0.0, 0.0, 1e300, 1.0}), "");
}

}  // namespace
}  // namespace ari_social_sim::model
