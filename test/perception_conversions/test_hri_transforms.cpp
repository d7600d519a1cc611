#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "perception_conversions/hri_messages.hpp"

// The ROS4HRI frames perception publishes: a face's frame points out of the face, turned with
// the head and tipped down while the person nods (docs/perception.md).

namespace ari_social_sim::nodes {
namespace {

const geometry_msgs::TransformStamped& find(
    const std::vector<geometry_msgs::TransformStamped>& transforms, const std::string& child) {
  for (const geometry_msgs::TransformStamped& t : transforms) {
    if (t.child_frame_id == child) {
      return t;
    }
  }
  throw std::runtime_error("no frame " + child);
}

Eigen::Vector3d x_axis_of(const geometry_msgs::TransformStamped& t) {
  const geometry_msgs::Quaternion& q = t.transform.rotation;
  return Eigen::Quaterniond(q.w, q.x, q.y, q.z) * Eigen::Vector3d::UnitX();
}

TEST(HriTransforms, ANoddingFaceTipsItsFrameDown) {
  perception::PerceptionFrame frame;
  frame.has_ari = true;
  perception::PerceivedFace face;
  face.face_id = "abcde";
  face.X_map_face = {{2.0, 0.0}, M_PI};  // 2 m ahead of ARI, facing it
  face.gaze_rad = M_PI;
  face.pitch_rad = 0.2;
  frame.faces.push_back(face);
  std_msgs::Header header;
  header.frame_id = "map";
  const auto transforms = hri_transforms(frame, {}, header, "base_footprint", false);

  const Eigen::Vector3d out_of_face = x_axis_of(find(transforms, "face_abcde"));
  EXPECT_NEAR(out_of_face.x(), -std::cos(0.2), 1e-9);
  EXPECT_NEAR(out_of_face.y(), 0.0, 1e-9);
  EXPECT_NEAR(out_of_face.z(), -std::sin(0.2), 1e-9);

  frame.faces[0].pitch_rad = 0.0;
  const auto level = hri_transforms(frame, {}, header, "base_footprint", false);
  EXPECT_NEAR(x_axis_of(find(level, "face_abcde")).z(), 0.0, 1e-12);
}

TEST(HriTransforms, ASeatedPersonsBodyHeadAndFaceFramesAreLower) {
  perception::PerceptionFrame frame;
  frame.has_ari = true;
  perception::PerceivedBody body;
  body.body_id = "bseat";
  body.X_map_body = {{2.0, 0.0}, M_PI};
  body.posture = world::Posture::kSitting;
  frame.bodies.push_back(body);
  body.body_id = "bstand";
  body.posture = world::Posture::kStanding;
  frame.bodies.push_back(body);
  perception::PerceivedFace face;
  face.face_id = "fseat";
  face.X_map_face = {{2.0, 0.0}, M_PI};
  face.posture = world::Posture::kSitting;
  frame.faces.push_back(face);
  std_msgs::Header header;
  header.frame_id = "map";
  const perception::HumanModelConfig model;  // hips 0.95 / 0.55 m, eyes 1.60 / 1.20 m
  const auto transforms = hri_transforms(frame, model, header, "base_footprint", false);
  EXPECT_DOUBLE_EQ(find(transforms, "body_bseat").transform.translation.z, 0.55);
  EXPECT_DOUBLE_EQ(find(transforms, "head_bseat").transform.translation.z, 1.20 - 0.55);
  EXPECT_DOUBLE_EQ(find(transforms, "face_fseat").transform.translation.z, 1.20);
  EXPECT_DOUBLE_EQ(find(transforms, "body_bstand").transform.translation.z, 0.95);
  EXPECT_DOUBLE_EQ(find(transforms, "head_bstand").transform.translation.z, 1.60 - 0.95);
}

}  // namespace
}  // namespace ari_social_sim::nodes
