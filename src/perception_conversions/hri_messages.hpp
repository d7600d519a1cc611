#pragma once

#include <geometry_msgs/TransformStamped.h>
#include <std_msgs/Header.h>

#include <string>
#include <vector>

#include "ari_social_sim/BodyPosture.h"
#include "ari_social_sim/EngagementLevel.h"
#include "ari_social_sim/Expression.h"
#include "ari_social_sim/Gaze.h"
#include "ari_social_sim/Group.h"
#include "ari_social_sim/IdsList.h"
#include "ari_social_sim/IdsMatch.h"
#include "ari_social_sim/LiveSpeech.h"
#include "ari_social_sim/NormalizedRegionOfInterest2D.h"
#include "ari_social_sim/SoftBiometrics.h"
#include "ari_social_sim/perception/candidate_matches.hpp"
#include "ari_social_sim/perception/group_perception.hpp"
#include "ari_social_sim/perception/perception_config.hpp"
#include "ari_social_sim/perception/perception_frame.hpp"

// The ROS4HRI messages (hri_msgs 0.9.0 layouts, REP-155 topics) of a perception frame.

namespace ari_social_sim::nodes {

IdsList ids_msg(const std::vector<std::string>& ids, const std_msgs::Header& header);
NormalizedRegionOfInterest2D roi_msg(const perception::ImageRegion& region, double confidence,
                                     const std_msgs::Header& header);
/// Age rounded to whole years; the world's non-identified gender is UNDEFINED.
SoftBiometrics softbiometrics_msg(const perception::PerceivedFace& face,
                                  const std_msgs::Header& header);
/// The hri_msgs/Expression constant of the emotion's expression (perception::expression_of: the
/// constants' values include their double quotes) with its valence and arousal.
Expression expression_msg(const perception::PerceivedFace& face, const std_msgs::Header& header);
/// hri_msgs/BodyPosture STANDING or SITTING: the posture the body shows.
BodyPosture posture_msg(const perception::PerceivedBody& body, const std_msgs::Header& header);
LiveSpeech speech_msg(const perception::SpeechResult& result, const std::string& language,
                      const std_msgs::Header& header);
EngagementLevel engagement_msg(perception::EngagementLevel level, const std_msgs::Header& header);
Group group_msg(const perception::PerceivedGroup& group, const std_msgs::Header& header);
Gaze gaze_msg(const perception::GazeRelation& gaze, const std_msgs::Header& header);
IdsMatch match_msg(const perception::CandidateMatch& match);

/// Frame names of REP-155.
std::string body_frame(const std::string& body_id);
std::string head_frame(const std::string& body_id);
std::string face_frame(const std::string& face_id);
std::string gaze_frame(const std::string& face_id);
std::string voice_frame(const std::string& voice_id);
std::string person_frame(const std::string& person_id);

/// Every ROS4HRI frame of `frame` stamped `header.stamp`: body_<id> at the mid-hips (x forward),
/// head_<body id> above it at eye height (where hri_person_manager places a person seen by the
/// body only), face_<id> at the sellion (x out of the face), voice_<id>, all children of
/// `robot_frame` (ARI's base_footprint, where `frame.X_map_base` is); gaze_<id> as a child of
/// face_<id> with its z axis along the gaze (optical convention); with `with_persons`,
/// person_<id> in `header.frame_id` (the map) at the person's last known head position while
/// location_confidence > 0.
std::vector<geometry_msgs::TransformStamped> hri_transforms(
    const perception::PerceptionFrame& frame, const perception::HumanModelConfig& human_model,
    const std_msgs::Header& header, const std::string& robot_frame, bool with_persons);

/// What hri_perception_node publishes once per frame besides the per-id subtopics, so that
/// run_episodes records exactly what the node publishes: the tracked id lists (headers in
/// `robot_frame`), `matches` as IdsMatch, one Gaze per relation, and the ROS4HRI frames (none
/// without ARI). Without `with_persons` (detectors mode) the person lists and frames are left
/// empty: a person manager publishes them. Groups are group_detection_node's (group_msg).
struct HriFrameMessages {
  IdsList faces_tracked, bodies_tracked, voices_tracked, persons_tracked, persons_known;
  std::vector<IdsMatch> matches;
  std::vector<Gaze> gazes;
  std::vector<geometry_msgs::TransformStamped> transforms;
};
HriFrameMessages hri_frame_messages(const perception::PerceptionFrame& frame,
                                    const std::vector<perception::CandidateMatch>& matches,
                                    bool with_persons,
                                    const perception::HumanModelConfig& human_model,
                                    const ros::Time& stamp, const std::string& robot_frame,
                                    const std::string& map_frame);

}  // namespace ari_social_sim::nodes
