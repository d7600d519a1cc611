#include <gtest/gtest.h>

#include <string>

#include "ari_social_sim/batch/group_streams.hpp"

namespace ari_social_sim::batch {
namespace {

// Humans 10, 11, 12 in group 1, 20 and 21 in group 2, 30 alone in group 3.
world::WorldSnapshot world_of_three_groups() {
  world::WorldSnapshot world;
  world.groups = {{1, {10, 11, 12}}, {2, {20, 21}}, {3, {30}}};
  return world;
}

void add_body(perception::PerceptionFrame& frame, model::ObjectId human, double x, double theta) {
  perception::PerceivedBody body;
  body.human = human;
  body.body_id = "b" + std::to_string(human);
  body.person_id = "p" + std::to_string(human);
  body.X_map_body.position = {x, 1.0};
  body.X_map_body.theta = theta;
  frame.bodies.push_back(body);
}

void add_person(perception::PerceptionFrame& frame, model::ObjectId human, bool body) {
  perception::PersonReport person;
  person.human = human;
  person.person_id = "p" + std::to_string(human);
  person.tracked = true;
  person.body_id = body ? "b" + std::to_string(human) : "";
  person.face_id = body ? "" : "f" + std::to_string(human);
  frame.persons.push_back(person);
}

// 10, 11 and 20 tracked at their bodies; 12 by the face only (no body: GCFF is not given them);
// 21 and 30 not perceived. Group 1 keeps 10 and 11; group 2 keeps only 20 and is left out; group
// 3 has one member in the world and is no group.
perception::PerceptionFrame frame_seeing_part_of_them() {
  perception::PerceptionFrame frame;
  add_body(frame, 10, 1.0, 0.5);
  add_body(frame, 11, 2.0, -2.5);
  add_body(frame, 20, 5.123456, 3.14159265);
  add_person(frame, 10, true);
  add_person(frame, 11, true);
  add_person(frame, 12, false);
  add_person(frame, 20, true);
  return frame;
}

TEST(GroupStreams, TruthKeepsTheGroupsWithTwoMembersPerceivedByTheirPerceivedIds) {
  GroupStreams streams;
  streams.add(world_of_three_groups(), frame_seeing_part_of_them());
  streams.add(world_of_three_groups(), frame_seeing_part_of_them());
  EXPECT_EQ(streams.features_csv(),
            "frame,person_id,x,y,theta\n"
            "0,p10,1.0000,1.0000,0.50000\n"
            "0,p11,2.0000,1.0000,-2.50000\n"
            "0,p20,5.1235,1.0000,3.14159\n"
            "1,p10,1.0000,1.0000,0.50000\n"
            "1,p11,2.0000,1.0000,-2.50000\n"
            "1,p20,5.1235,1.0000,3.14159\n");
  EXPECT_EQ(streams.groundtruth_csv(),
            "frame,group,person_id\n"
            "0,1,p10\n"
            "0,1,p11\n"
            "1,1,p10\n"
            "1,1,p11\n");
  EXPECT_EQ(streams.frames_csv(), "frame\n0\n1\n");
  const GroupStreamCounts& counts = streams.counts();
  EXPECT_EQ(counts.frames, 2u);
  EXPECT_EQ(counts.feature_rows, 6u);  // 3 people x 2 frames
  EXPECT_EQ(counts.world_groups, 4u);  // groups 1 and 2 (3 has one member) x 2 frames
  EXPECT_EQ(counts.truth_groups, 2u);  // group 1 x 2 frames
  EXPECT_EQ(counts.truth_rows, 4u);
}

TEST(GroupStreams, AFrameWithNobodyIsStillAFrame) {
  GroupStreams streams;
  streams.add(world_of_three_groups(), perception::PerceptionFrame{});
  EXPECT_EQ(streams.features_csv(), "frame,person_id,x,y,theta\n");
  EXPECT_EQ(streams.groundtruth_csv(), "frame,group,person_id\n");
  EXPECT_EQ(streams.frames_csv(), "frame\n0\n");
  EXPECT_EQ(streams.counts().world_groups, 2u);
  EXPECT_EQ(streams.counts().truth_groups, 0u);
}

}  // namespace
}  // namespace ari_social_sim::batch
