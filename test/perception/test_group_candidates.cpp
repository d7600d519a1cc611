// group_candidates_of: one candidate per perceived body, named by its person, at the body's noisy
// pose, in the frame's order; nothing else of the frame (faces, voices, ARI) is a candidate.

#include <gtest/gtest.h>

#include "ari_social_sim/perception/group_candidates.hpp"
#include "ari_social_sim/perception/perception_pipeline.hpp"
#include "perception_scenes.hpp"

namespace ari_social_sim::perception {
namespace {

PerceivedBody body(model::ObjectId human, const std::string& body_id, double x, double y,
                   double theta) {
  PerceivedBody b;
  b.human = human;
  b.body_id = body_id;
  b.person_id = person_id_of(human);
  b.X_map_body = {{x, y}, theta};
  return b;
}

TEST(GroupCandidates, OnePerBodyNamedByPersonAtTheBodyPose) {
  PerceptionFrame frame;
  frame.has_ari = true;
  frame.X_map_base = {{1.0, 1.0}, 0.5};  // ARI is never a candidate
  frame.bodies = {body(10, "abcde", 2.5, -1.0, 3.0), body(12, "fghij", 4.0, 0.25, -1.5)};
  PerceivedFace face;  // a face alone gives no facing of the body
  face.person_id = person_id_of(11);
  frame.faces = {face};
  const std::vector<GcffPerson> candidates = group_candidates_of(frame);
  ASSERT_EQ(candidates.size(), 2u);
  EXPECT_EQ(candidates[0].id, "human10");
  EXPECT_DOUBLE_EQ(candidates[0].x, 2.5);
  EXPECT_DOUBLE_EQ(candidates[0].y, -1.0);
  EXPECT_DOUBLE_EQ(candidates[0].theta, 3.0);
  EXPECT_EQ(candidates[1].id, "human12");
  EXPECT_DOUBLE_EQ(candidates[1].x, 4.0);
  EXPECT_DOUBLE_EQ(candidates[1].y, 0.25);
  EXPECT_DOUBLE_EQ(candidates[1].theta, -1.5);
}

TEST(GroupCandidates, AFrameWithoutBodiesHasNone) {
  EXPECT_TRUE(group_candidates_of(PerceptionFrame{}).empty());
}

TEST(GroupCandidates, FromThePipelineTheSeenBodiesOnly) {
  // Errors off: two people in front of ARI at 2 m and 3 m, one 2 m behind it (outside the
  // fisheye's 180 degrees), so two candidates at their true poses.
  PerceptionPipeline pipeline(test::config_without_errors());
  world::WorldSnapshot snapshot = test::snapshot_with_ari(1.0);
  snapshot.humans = {test::human_at(10, 2.0, 0.5, 3.0), test::human_at(11, 3.0, -0.5, 2.5),
                     test::human_at(12, -2.0, 0.0, 0.0)};
  const PerceptionFrame& frame = pipeline.update(snapshot);
  const std::vector<GcffPerson> candidates = group_candidates_of(frame);
  ASSERT_EQ(candidates.size(), 2u);
  EXPECT_EQ(candidates[0].id, "human10");
  EXPECT_DOUBLE_EQ(candidates[0].x, 2.0);
  EXPECT_DOUBLE_EQ(candidates[0].y, 0.5);
  EXPECT_DOUBLE_EQ(candidates[0].theta, 3.0);
  EXPECT_EQ(candidates[1].id, "human11");
  EXPECT_DOUBLE_EQ(candidates[1].theta, 2.5);
}

}  // namespace
}  // namespace ari_social_sim::perception
