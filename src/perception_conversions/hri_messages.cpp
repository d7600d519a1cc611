#include "hri_messages.hpp"

#include <cmath>

#include "ari_social_sim/perception/expression.hpp"
#include "world_conversions/marker_builder.hpp"

namespace ari_social_sim::nodes {
namespace {

geometry_msgs::TransformStamped transform(const std_msgs::Header& header, const std::string& parent,
                                          const std::string& child, double x, double y, double z,
                                          double yaw) {
  geometry_msgs::TransformStamped t;
  t.header.stamp = header.stamp;
  t.header.frame_id = parent;
  t.child_frame_id = child;
  t.transform.translation.x = x;
  t.transform.translation.y = y;
  t.transform.translation.z = z;
  t.transform.rotation = yaw_quaternion(yaw);
  return t;
}

// Yaw about z, then pitch about the turned y axis (positive: x tips down), as one quaternion.
geometry_msgs::Quaternion yaw_pitch_quaternion(double yaw, double pitch) {
  const double cz = std::cos(0.5 * yaw), sz = std::sin(0.5 * yaw);
  const double cp = std::cos(0.5 * pitch), sp = std::sin(0.5 * pitch);
  geometry_msgs::Quaternion q;
  q.w = cz * cp;
  q.x = -sz * sp;
  q.y = cz * sp;
  q.z = sz * cp;
  return q;
}

// Rotation of an optical frame (z forward, x right, y down) whose z axis turns `yaw` from the x
// axis of its parent (x forward, z up): yaw about z, then roll -pi/2 about x and yaw -pi/2 about
// z of the optical convention, composed as one quaternion.
geometry_msgs::Quaternion optical_looking(double yaw) {
  // q(yaw about z) * q(rpy = -pi/2, 0, -pi/2) = q(yaw) * (0.5, -0.5, 0.5, -0.5) in (x, y, z, w).
  const double cz = std::cos(0.5 * yaw), sz = std::sin(0.5 * yaw);
  const double ox = -0.5, oy = 0.5, oz = -0.5, ow = 0.5;
  geometry_msgs::Quaternion q;
  q.w = cz * ow - sz * oz;
  q.x = cz * ox - sz * oy;
  q.y = cz * oy + sz * ox;
  q.z = cz * oz + sz * ow;
  return q;
}

}  // namespace

IdsList ids_msg(const std::vector<std::string>& ids, const std_msgs::Header& header) {
  IdsList msg;
  msg.header = header;
  msg.ids = ids;
  return msg;
}

NormalizedRegionOfInterest2D roi_msg(const perception::ImageRegion& region, double confidence,
                                     const std_msgs::Header& header) {
  NormalizedRegionOfInterest2D msg;
  msg.header = header;
  msg.xmin = static_cast<float>(region.xmin);
  msg.ymin = static_cast<float>(region.ymin);
  msg.xmax = static_cast<float>(region.xmax);
  msg.ymax = static_cast<float>(region.ymax);
  msg.c = static_cast<float>(confidence);
  return msg;
}

SoftBiometrics softbiometrics_msg(const perception::PerceivedFace& face,
                                  const std_msgs::Header& header) {
  SoftBiometrics msg;
  msg.header = header;
  msg.age = static_cast<uint8_t>(std::lround(face.age_years));
  msg.age_confidence = static_cast<float>(face.age_confidence);
  switch (face.gender) {
    case model::Gender::kFemale:
      msg.gender = SoftBiometrics::FEMALE;
      break;
    case model::Gender::kMale:
      msg.gender = SoftBiometrics::MALE;
      break;
    case model::Gender::kNonIdentified:
      msg.gender = SoftBiometrics::UNDEFINED;
      break;
  }
  msg.gender_confidence = static_cast<float>(face.gender_confidence);
  return msg;
}

BodyPosture posture_msg(const perception::PerceivedBody& body, const std_msgs::Header& header) {
  BodyPosture msg;
  msg.header = header;
  msg.posture =
      body.posture == world::Posture::kSitting ? BodyPosture::SITTING : BodyPosture::STANDING;
  return msg;
}

Expression expression_msg(const perception::PerceivedFace& face, const std_msgs::Header& header) {
  const perception::ExpressionLabel label = perception::expression_of(face.emotion);
  Expression msg;
  msg.header = header;
  // hri_msgs' string constants keep their quotes (`string ANGRY="angry"` is "\"angry\""), and
  // consumers compare with them: send the constant, not the bare word.
  switch (face.emotion) {
    case model::Emotion::kHappy:
      msg.expression = Expression::HAPPY;
      break;
    case model::Emotion::kAngry:
      msg.expression = Expression::ANGRY;
      break;
    case model::Emotion::kDisturbed:
      msg.expression = Expression::SCARED;
      break;
    case model::Emotion::kNeutral:
      msg.expression = Expression::NEUTRAL;
      break;
  }
  msg.valence = static_cast<float>(label.valence);
  msg.arousal = static_cast<float>(label.arousal);
  msg.confidence = static_cast<float>(face.emotion_confidence);
  return msg;
}

LiveSpeech speech_msg(const perception::SpeechResult& result, const std::string& language,
                      const std_msgs::Header& header) {
  LiveSpeech msg;
  msg.header = header;
  msg.incremental = result.incremental;
  msg.final = result.final_text;
  msg.confidence = result.confidence;
  msg.language = language;
  return msg;
}

EngagementLevel engagement_msg(perception::EngagementLevel level, const std_msgs::Header& header) {
  EngagementLevel msg;
  msg.header = header;
  msg.level = static_cast<uint8_t>(level);
  return msg;
}

Group group_msg(const perception::PerceivedGroup& group, const std_msgs::Header& header) {
  Group msg;
  msg.header = header;
  msg.group_id = group.group_id;
  msg.members = group.members;
  return msg;
}

Gaze gaze_msg(const perception::GazeRelation& gaze, const std_msgs::Header& header) {
  Gaze msg;
  msg.header = header;
  msg.sender = gaze.sender;
  msg.receiver = gaze.receiver;
  return msg;
}

IdsMatch match_msg(const perception::CandidateMatch& match) {
  IdsMatch msg;
  msg.id1 = match.id1;
  msg.id1_type = static_cast<int8_t>(match.kind1);
  msg.id2 = match.id2;
  msg.id2_type = static_cast<int8_t>(match.kind2);
  msg.confidence = static_cast<float>(match.confidence);
  return msg;
}

std::string body_frame(const std::string& body_id) {
  return "body_" + body_id;
}
std::string head_frame(const std::string& body_id) {
  return "head_" + body_id;
}
std::string face_frame(const std::string& face_id) {
  return "face_" + face_id;
}
std::string gaze_frame(const std::string& face_id) {
  return "gaze_" + face_id;
}
std::string voice_frame(const std::string& voice_id) {
  return "voice_" + voice_id;
}
std::string person_frame(const std::string& person_id) {
  return "person_" + person_id;
}

std::vector<geometry_msgs::TransformStamped> hri_transforms(
    const perception::PerceptionFrame& frame, const perception::HumanModelConfig& human_model,
    const std_msgs::Header& header, const std::string& robot_frame, bool with_persons) {
  std::vector<geometry_msgs::TransformStamped> transforms;
  for (const perception::PerceivedBody& body : frame.bodies) {
    const core::Pose2 X_base_body = body.X_map_body.relative_to(frame.X_map_base);
    const double hips = human_model.hip_height(body.posture);
    transforms.push_back(transform(header, robot_frame, body_frame(body.body_id),
                                   X_base_body.position.x(), X_base_body.position.y(), hips,
                                   X_base_body.theta));
    transforms.push_back(transform(header, body_frame(body.body_id), head_frame(body.body_id), 0, 0,
                                   human_model.eye_height(body.posture) - hips, 0));
  }
  for (const perception::PerceivedFace& face : frame.faces) {
    const core::Pose2 X_base_face = face.X_map_face.relative_to(frame.X_map_base);
    geometry_msgs::TransformStamped face_pose = transform(
        header, robot_frame, face_frame(face.face_id), X_base_face.position.x(),
        X_base_face.position.y(), human_model.eye_height(face.posture), X_base_face.theta);
    // A nod tips the face, and the gaze frame with it.
    face_pose.transform.rotation = yaw_pitch_quaternion(X_base_face.theta, face.pitch_rad);
    transforms.push_back(face_pose);
    geometry_msgs::TransformStamped gaze =
        transform(header, face_frame(face.face_id), gaze_frame(face.face_id), 0, 0, 0, 0);
    gaze.transform.rotation = optical_looking(face.gaze_rad - face.X_map_face.theta);
    transforms.push_back(gaze);
  }
  for (const perception::PerceivedVoice& voice : frame.voices) {
    const core::Pose2 X_base_voice = core::Pose2{voice.position, 0.0}.relative_to(frame.X_map_base);
    transforms.push_back(transform(header, robot_frame, voice_frame(voice.voice_id),
                                   X_base_voice.position.x(), X_base_voice.position.y(),
                                   human_model.eye_height_m, 0.0));
  }
  for (const perception::PersonReport& person : frame.persons) {
    if (with_persons && person.location_confidence > 0.0) {
      transforms.push_back(transform(header, header.frame_id, person_frame(person.person_id),
                                     person.location.x(), person.location.y(),
                                     human_model.eye_height_m, 0.0));
    }
  }
  return transforms;
}

HriFrameMessages hri_frame_messages(const perception::PerceptionFrame& frame,
                                    const std::vector<perception::CandidateMatch>& matches,
                                    bool with_persons,
                                    const perception::HumanModelConfig& human_model,
                                    const ros::Time& stamp, const std::string& robot_frame,
                                    const std::string& map_frame) {
  std_msgs::Header header;
  header.stamp = stamp;
  header.frame_id = robot_frame;
  HriFrameMessages out;
  std::vector<std::string> body_ids, face_ids, voice_ids, tracked, known;
  for (const perception::CandidateMatch& match : matches) {
    out.matches.push_back(match_msg(match));
  }
  for (const perception::PerceivedBody& body : frame.bodies) {
    body_ids.push_back(body.body_id);
  }
  for (const perception::PerceivedFace& face : frame.faces) {
    face_ids.push_back(face.face_id);
  }
  for (const perception::PerceivedVoice& voice : frame.voices) {
    voice_ids.push_back(voice.voice_id);
  }
  if (with_persons) {
    for (const perception::PersonReport& person : frame.persons) {
      known.push_back(person.person_id);
      if (person.tracked) {
        tracked.push_back(person.person_id);
      }
    }
  }
  for (const perception::GazeRelation& gaze : frame.gazes) {
    out.gazes.push_back(gaze_msg(gaze, header));
  }
  if (frame.has_ari) {
    std_msgs::Header map_header = header;
    map_header.frame_id = map_frame;
    out.transforms = hri_transforms(frame, human_model, map_header, robot_frame, with_persons);
  }
  out.faces_tracked = ids_msg(face_ids, header);
  out.bodies_tracked = ids_msg(body_ids, header);
  out.voices_tracked = ids_msg(voice_ids, header);
  out.persons_tracked = ids_msg(tracked, header);
  out.persons_known = ids_msg(known, header);
  return out;
}

}  // namespace ari_social_sim::nodes
