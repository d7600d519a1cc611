#include <gtest/gtest.h>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/perception/group_perception.hpp"

namespace ari_social_sim::perception {
namespace {

// A perceived body of human `human` at (x, y) facing the point (cx, cy).
PerceivedBody facing(world::ObjectId human, double x, double y, double cx, double cy) {
  PerceivedBody body;
  body.human = human;
  body.person_id = person_id_of(human);
  body.X_map_body = {{x, y}, std::atan2(cy - y, cx - x)};
  return body;
}

TEST(GroupPerception, GroupsOfPersonsWithStableIds) {
  GroupPerception groups(GroupConfig{});
  // Three around (2, 2) at 0.7 m, two face to face around (6, 0), one alone looking away.
  std::vector<PerceivedBody> bodies = {
      facing(10, 2.7, 2.0, 2.0, 2.0),  facing(11, 1.65, 2.6, 2.0, 2.0),
      facing(12, 1.65, 1.4, 2.0, 2.0), facing(20, 5.4, 0.0, 6.0, 0.0),
      facing(21, 6.6, 0.0, 6.0, 0.0),  facing(30, 9.0, 5.0, 20.0, 5.0)};
  std::vector<PerceivedGroup> detected;
  groups.update(bodies, detected);
  ASSERT_EQ(detected.size(), 2u);
  EXPECT_EQ(detected[0].members, (std::vector<std::string>{"human10", "human11", "human12"}));
  EXPECT_EQ(detected[1].members, (std::vector<std::string>{"human20", "human21"}));
  EXPECT_NEAR(detected[0].centre.x(), 2.0, 0.15);
  EXPECT_NEAR(detected[0].centre.y(), 2.0, 0.15);
  const std::string first = detected[0].group_id, second = detected[1].group_id;
  EXPECT_NE(first, second);

  // Frame after frame, with one member of the triple gone, the ids stay.
  for (int frame = 0; frame < 5; ++frame) {
    groups.update(bodies, detected);
    EXPECT_EQ(detected[0].group_id, first);
    EXPECT_EQ(detected[1].group_id, second);
  }
  bodies.erase(bodies.begin() + 2);
  groups.update(bodies, detected);
  ASSERT_EQ(detected.size(), 2u);
  EXPECT_EQ(detected[0].members, (std::vector<std::string>{"human10", "human11"}));
  EXPECT_EQ(detected[0].group_id, first);
  EXPECT_EQ(detected[1].group_id, second);
}

}  // namespace
}  // namespace ari_social_sim::perception
