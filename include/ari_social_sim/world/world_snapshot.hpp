#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "ari_social_sim/core/pose2.hpp"
#include "ari_social_sim/model/fformation_arrangement.hpp"
#include "ari_social_sim/model/object_id.hpp"
#include "ari_social_sim/model/person_attributes.hpp"
#include "ari_social_sim/world/human.hpp"
#include "ari_social_sim/world/walking_group.hpp"

namespace ari_social_sim::world {

class Simulation;
class SpeechGenerator;

struct SpeechSnapshot {
  std::string act;
  std::string content;
  std::string current_word;
  uint32_t word_index{0};
  bool is_speaking{false};
  double start_s{0.0};
  std::string previous_act;
  std::string previous_content;
  double words_per_minute{0.0};  // word k of content starts k * 60 / words_per_minute after start_s
};

struct GazeSnapshot {
  model::ObjectId target{model::kNoObject};
  double direction_rad{0.0};
  double since_s{0.0};
};

struct HumanSnapshot {
  model::ObjectId id{model::kNoObject};
  std::string name;
  std::string role;
  core::Pose2 pose;
  Eigen::Vector2d velocity_mps{Eigen::Vector2d::Zero()};
  double angular_velocity_rps{0.0};
  double age_years{0.0};
  model::Gender gender{model::Gender::kNonIdentified};
  bool mask{false};
  model::Emotion emotion{model::Emotion::kNeutral};
  MotionMode motion_mode{MotionMode::kIdle};
  std::optional<core::Pose2> goal;
  model::ObjectId group_id{model::kNoObject};
  ReactionProfile reaction{ReactionProfile::kIgnore};
  GazeSnapshot gaze;
  double head_pitch_rad{0.0};  // positive: down; a nod (docs/world.md "Conversation")
  SpeechSnapshot speech;
  PostureState posture;  // standing or sitting, and how far a change into it has got
  double walked_m{0.0};  // on foot, since entering the world: where the figures' gait is
};

struct AriSnapshot {
  model::ObjectId id{model::kNoObject};
  core::Pose2 pose;  // base_footprint
  double linear_mps{0.0};
  double angular_rps{0.0};
  double head_pan_rad{0.0};
  double head_pan_velocity_rps{0.0};
  SpeechSnapshot speech;
};

struct GroupSnapshot {
  model::ObjectId id{model::kNoObject};
  std::vector<model::ObjectId> members;
  Eigen::Vector2d centre{Eigen::Vector2d::Zero()};
  double ospace_radius_m{0.0};
  model::Arrangement arrangement{model::Arrangement::kCircle};  // as kept now
  double heading_rad{0.0};                          // bearing of the first row from the centre
  model::ObjectId robot_joining{model::kNoObject};  // ARI while the members make room for it
  bool converses{false};  // the group has a conversation (GroupConversation); the rest follows it
  model::ObjectId speaker{model::kNoObject};    // holding the floor; none in a silence
  model::ObjectId addressee{model::kNoObject};  // of the speaker's utterance; none: the group
  double utterance_end_s{0.0};  // when the current (or last) utterance ends: the next transition
};

struct WalkingGroupSnapshot {
  model::ObjectId id{model::kNoObject};
  std::vector<model::ObjectId> members;
  WalkingFormation formation{WalkingFormation::kSideBySide};  // walked now
  Eigen::Vector2d leader{Eigen::Vector2d::Zero()};            // the virtual leader on the route
  double heading_rad{0.0};                                    // walking direction
  core::Pose2 goal;
  ArrivalAction on_arrival{ArrivalAction::kStop};
  bool waiting{false};  // for a member who fell behind
  bool arrived{false};
};

/// Every agent's ground truth after a step, as plain data: what /sim/world_state carries and what
/// tests and the batch tool read.
struct WorldSnapshot {
  double time_s{0.0};
  uint64_t step{0};
  std::optional<AriSnapshot> ari;
  std::vector<HumanSnapshot> humans;  // ordered by id
  std::vector<GroupSnapshot> groups;  // ordered by id
  // Ordered by id.
  std::vector<WalkingGroupSnapshot> walking_groups;

  static WorldSnapshot of(const Simulation& simulation);
};

SpeechSnapshot snapshot_of(const SpeechGenerator& speech);

}  // namespace ari_social_sim::world
