// What a frame tells the consumers of persons (tracked_persons_of), and group_candidates_of: each
// tracked person at their body, named by person id, at the body's noisy pose, in the persons'
// order; a person without a body (a face or voice only) or not tracked is no candidate, and
// neither is anything else of the frame (ARI).

#include <gtest/gtest.h>

#include "ari_social_sim/perception/group_candidates.hpp"
#include "ari_social_sim/perception/perception_pipeline.hpp"
#include "ari_social_sim/perception/tracked_persons.hpp"
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

PersonReport person(model::ObjectId human, const std::string& body_id, bool tracked = true) {
  PersonReport p;
  p.human = human;
  p.person_id = person_id_of(human);
  p.body_id = body_id;
  p.tracked = tracked;
  return p;
}

// Humans 10 and 12 seen whole, 11 by the face only, 13 known but no longer tracked.
PerceptionFrame frame_of_four() {
  PerceptionFrame frame;
  frame.time_s = 4.5;
  frame.has_ari = true;
  frame.X_map_base = {{1.0, 1.0}, 0.5};  // ARI is never a candidate
  frame.bodies = {body(10, "abcde", 2.5, -1.0, 3.0), body(12, "fghij", 4.0, 0.25, -1.5)};
  PerceivedFace face;  // a face alone gives no facing of the body
  face.person_id = person_id_of(11);
  frame.faces = {face};
  frame.persons = {person(10, "abcde"), person(11, ""), person(12, "fghij"), person(13, "", false)};
  return frame;
}

TEST(TrackedPersons, TheTrackedPersonsInOrderWithTheirBodiesAtTheFramesTime) {
  const model::TrackedPersons tracked = tracked_persons_of(frame_of_four());
  ASSERT_EQ(tracked.persons.size(), 3u);
  EXPECT_EQ(tracked.persons[0].person_id, "human10");
  EXPECT_EQ(tracked.persons[0].body_id, "abcde");
  EXPECT_EQ(tracked.persons[1].person_id, "human11");
  EXPECT_EQ(tracked.persons[1].body_id, "");
  EXPECT_EQ(tracked.persons[2].body_id, "fghij");
  const std::optional<model::BodyPlacement> placed = tracked.locate_body("fghij");
  ASSERT_TRUE(placed.has_value());
  EXPECT_EQ(placed->stamp_s, 4.5);
  EXPECT_EQ(placed->pose.position.x(), 4.0);
  EXPECT_EQ(placed->pose.position.y(), 0.25);
  EXPECT_EQ(placed->pose.theta, -1.5);
  EXPECT_FALSE(tracked.locate_body("zzzzz").has_value());
}

TEST(GroupCandidates, TrackedPersonsAtTheirBodyPoses) {
  const std::vector<GcffPerson> candidates = group_candidates_of(frame_of_four());
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

TEST(GroupCandidates, InThePersonsOrderWhereverTheirBodiesArePlaced) {
  // As group_detection_node gets them: a list in its own order, bodies placed by tf.
  model::TrackedPersons persons;
  persons.persons = {{"b_person", "b2"}, {"a_person", "b1"}, {"gone", "b9"}};
  persons.locate_body = [](const std::string& body) -> std::optional<model::BodyPlacement> {
    if (body == "b9") {
      return std::nullopt;  // tf cannot place it
    }
    return model::BodyPlacement{1.0, {{body == "b1" ? 1.0 : 2.0, 0.0}, 0.25}};
  };
  const std::vector<GcffPerson> candidates = group_candidates_of(persons);
  ASSERT_EQ(candidates.size(), 2u);
  EXPECT_EQ(candidates[0].id, "b_person");
  EXPECT_EQ(candidates[0].x, 2.0);
  EXPECT_EQ(candidates[1].id, "a_person");
  EXPECT_EQ(candidates[1].x, 1.0);
  EXPECT_EQ(candidates[1].theta, 0.25);
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
