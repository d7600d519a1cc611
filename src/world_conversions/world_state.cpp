#include "world_state.hpp"

#include <cmath>

#include "ari_social_sim/core/number_text.hpp"
#include "ari_social_sim/world/map_sensor.hpp"
#include "ari_social_sim/world/simulation.hpp"

namespace ari_social_sim::nodes {

geometry_msgs::Pose2D to_msg(const core::Pose2& pose) {
  geometry_msgs::Pose2D msg;
  msg.x = pose.position.x();
  msg.y = pose.position.y();
  msg.theta = pose.theta;
  return msg;
}

core::Pose2 from_msg(const geometry_msgs::Pose2D& msg) {
  return {{msg.x, msg.y}, msg.theta};
}

namespace {

SpeechState to_msg(const world::SpeechSnapshot& speech) {
  SpeechState msg;
  msg.act = speech.act;
  msg.content = speech.content;
  msg.current_word = speech.current_word;
  msg.word_index = speech.word_index;
  msg.is_speaking = speech.is_speaking;
  msg.start_time = speech.start_s;
  msg.words_per_minute = speech.words_per_minute;
  msg.previous_act = speech.previous_act;
  msg.previous_content = speech.previous_content;
  return msg;
}

world::SpeechSnapshot from_msg(const SpeechState& msg) {
  world::SpeechSnapshot speech;
  speech.act = msg.act;
  speech.content = msg.content;
  speech.current_word = msg.current_word;
  speech.word_index = msg.word_index;
  speech.is_speaking = msg.is_speaking;
  speech.start_s = msg.start_time;
  speech.words_per_minute = msg.words_per_minute;
  speech.previous_act = msg.previous_act;
  speech.previous_content = msg.previous_content;
  return speech;
}

}  // namespace

world::PostureState posture_of(const HumanState& msg) {
  if (msg.posture == HumanState::POSTURE_UNSET ||
      !(msg.posture_progress >= 0.0f && msg.posture_progress <= 1.0f)) {
    return {};
  }
  return {msg.posture == HumanState::POSTURE_SITTING ? world::Posture::kSitting
                                                     : world::Posture::kStanding,
          msg.posture_progress};
}

WorldState to_msg(const world::WorldSnapshot& snapshot, const std::string& frame_id) {
  WorldState msg;
  msg.header.stamp = ros::Time(snapshot.time_s);
  msg.header.frame_id = frame_id;
  msg.step = snapshot.step;
  msg.has_ari = snapshot.ari.has_value();
  if (snapshot.ari) {
    const world::AriSnapshot& ari = *snapshot.ari;
    msg.ari.id = ari.id;
    msg.ari.pose = to_msg(ari.pose);
    msg.ari.linear_velocity = ari.linear_mps;
    msg.ari.angular_velocity = ari.angular_rps;
    msg.ari.head_pan = ari.head_pan_rad;
    msg.ari.head_pan_velocity = ari.head_pan_velocity_rps;
    msg.ari.speech = to_msg(ari.speech);
  }
  msg.humans.reserve(snapshot.humans.size());
  for (const world::HumanSnapshot& human : snapshot.humans) {
    HumanState h;
    h.id = human.id;
    h.name = human.name;
    h.role = human.role;
    h.pose = to_msg(human.pose);
    h.velocity.linear.x = human.velocity_mps.x();
    h.velocity.linear.y = human.velocity_mps.y();
    h.velocity.angular.z = human.angular_velocity_rps;
    h.age = static_cast<float>(human.age_years);
    h.gender = static_cast<uint8_t>(human.gender);
    h.mask = human.mask;
    h.emotion = static_cast<uint8_t>(human.emotion);
    h.motion_mode = static_cast<uint8_t>(human.motion_mode);
    h.has_goal = human.goal.has_value();
    if (human.goal) {
      h.goal = to_msg(*human.goal);
    }
    h.group_id = human.group_id;
    h.reaction = world::reaction_name(human.reaction);
    h.gaze.target_id = human.gaze.target;
    h.gaze.direction = human.gaze.direction_rad;
    h.gaze.since = human.gaze.since_s;
    h.head_pitch = human.head_pitch_rad;
    h.speech = to_msg(human.speech);
    h.posture = human.posture.posture == world::Posture::kSitting ? HumanState::POSTURE_SITTING
                                                                  : HumanState::POSTURE_STANDING;
    h.posture_progress = static_cast<float>(human.posture.progress);
    h.walked_distance = human.walked_m;
    msg.humans.push_back(std::move(h));
  }
  for (const world::GroupSnapshot& group : snapshot.groups) {
    GroupState g;
    g.id = group.id;
    g.members = group.members;
    g.centre.x = group.centre.x();
    g.centre.y = group.centre.y();
    g.ospace_radius = group.ospace_radius_m;
    g.arrangement = model::to_string(group.arrangement);
    g.heading = group.heading_rad;
    g.robot_joining = group.robot_joining;
    g.converses = group.converses;
    g.speaker = group.speaker;
    g.addressee = group.addressee;
    g.utterance_end = group.utterance_end_s;
    msg.groups.push_back(std::move(g));
  }
  for (const world::WalkingGroupSnapshot& walking : snapshot.walking_groups) {
    WalkingGroupState w;
    w.id = walking.id;
    w.members = walking.members;
    w.formation = world::to_string(walking.formation);
    w.leader.x = walking.leader.x();
    w.leader.y = walking.leader.y();
    w.heading = walking.heading_rad;
    w.goal = to_msg(walking.goal);
    w.on_arrival = world::to_string(walking.on_arrival);
    w.waiting = walking.waiting;
    w.arrived = walking.arrived;
    msg.walking_groups.push_back(std::move(w));
  }
  return msg;
}

nav_msgs::OccupancyGrid to_msg(const model::OccupancyGrid& grid, const std::string& frame_id,
                               double stamp_s) {
  nav_msgs::OccupancyGrid msg;
  msg.header.stamp = ros::Time(stamp_s);
  msg.header.frame_id = frame_id;
  msg.info.map_load_time = msg.header.stamp;
  msg.info.resolution = static_cast<float>(grid.resolution_m);
  msg.info.width = static_cast<uint32_t>(grid.width);
  msg.info.height = static_cast<uint32_t>(grid.height);
  msg.info.origin.position.x = grid.origin.x();
  msg.info.origin.position.y = grid.origin.y();
  msg.info.origin.orientation.w = 1.0;
  msg.data = grid.cells;
  return msg;
}

world::WorldSnapshot from_msg(const WorldState& msg) {
  world::WorldSnapshot snapshot;
  snapshot.time_s = msg.header.stamp.toSec();
  snapshot.step = msg.step;
  if (msg.has_ari) {
    world::AriSnapshot ari;
    ari.id = msg.ari.id;
    ari.pose = from_msg(msg.ari.pose);
    ari.linear_mps = msg.ari.linear_velocity;
    ari.angular_rps = msg.ari.angular_velocity;
    ari.head_pan_rad = msg.ari.head_pan;
    ari.head_pan_velocity_rps = msg.ari.head_pan_velocity;
    ari.speech = from_msg(msg.ari.speech);
    snapshot.ari = ari;
  }
  snapshot.humans.reserve(msg.humans.size());
  for (const HumanState& h : msg.humans) {
    world::HumanSnapshot human;
    human.id = h.id;
    human.name = h.name;
    human.role = h.role;
    human.pose = from_msg(h.pose);
    human.velocity_mps = {h.velocity.linear.x, h.velocity.linear.y};
    human.angular_velocity_rps = h.velocity.angular.z;
    human.age_years = h.age;
    human.gender = static_cast<model::Gender>(h.gender);
    human.mask = h.mask;
    human.emotion = static_cast<model::Emotion>(h.emotion);
    human.motion_mode = static_cast<world::MotionMode>(h.motion_mode);
    if (h.has_goal) {
      human.goal = from_msg(h.goal);
    }
    human.group_id = h.group_id;
    // input_problem refuses other names; an empty one (an older publisher) is ignore.
    for (const auto& choice : world::kReactionProfiles) {
      if (h.reaction == choice.name) {
        human.reaction = choice.value;
      }
    }
    human.gaze = {h.gaze.target_id, h.gaze.direction, h.gaze.since};
    human.head_pitch_rad = h.head_pitch;
    human.speech = from_msg(h.speech);
    human.posture = posture_of(h);
    human.walked_m = h.walked_distance;
    snapshot.humans.push_back(std::move(human));
  }
  for (const GroupState& g : msg.groups) {
    // input_problem refuses an unknown arrangement before a message gets here.
    snapshot.groups.push_back(
        {g.id,
         g.members,
         {g.centre.x, g.centre.y},
         g.ospace_radius,
         core::parse_choice(g.arrangement, model::kArrangements, "arrangement"),
         g.heading,
         g.robot_joining,
         g.converses != 0,
         g.speaker,
         g.addressee,
         g.utterance_end});
  }
  for (const WalkingGroupState& w : msg.walking_groups) {
    // input_problem refuses an unknown formation or arrival before a message gets here.
    snapshot.walking_groups.push_back(
        {w.id,
         w.members,
         core::parse_choice(w.formation, world::kWalkingFormations, "formation"),
         {w.leader.x, w.leader.y},
         w.heading,
         from_msg(w.goal),
         core::parse_choice(w.on_arrival, world::kArrivalActions, "on_arrival"),
         w.waiting != 0,
         w.arrived != 0});
  }
  return snapshot;
}

model::OccupancyGrid from_msg(const nav_msgs::OccupancyGrid& msg) {
  model::OccupancyGrid grid;
  grid.origin = {msg.info.origin.position.x, msg.info.origin.position.y};
  grid.resolution_m = msg.info.resolution;
  grid.width = static_cast<int>(msg.info.width);
  grid.height = static_cast<int>(msg.info.height);
  grid.cells = msg.data;
  return grid;
}

namespace {

// Collects the first problem of a message, field by field.
class ProblemFinder {
 public:
  void finite(const std::string& field, double value) {
    if (!problem_ && !std::isfinite(value)) {
      problem_ = InputProblem{field, core::number_text(value) + ", not a finite number"};
    }
  }
  void at_most(const std::string& field, uint64_t value, uint64_t most) {
    if (!problem_ && value > most) {
      problem_ = InputProblem{field, std::to_string(value) + ", more than " + std::to_string(most)};
    }
  }
  void one_of(const std::string& field, uint64_t value, uint64_t first, uint64_t last) {
    if (!problem_ && (value < first || value > last)) {
      problem_ = InputProblem{field, std::to_string(value) + ", not one of " +
                                         std::to_string(first) + ".." + std::to_string(last)};
    }
  }
  void that(bool holds, const std::string& field, const std::string& what) {
    if (!problem_ && !holds) {
      problem_ = InputProblem{field, what};
    }
  }
  void pose(const std::string& field, const geometry_msgs::Pose2D& pose) {
    finite(field + ".x", pose.x);
    finite(field + ".y", pose.y);
    finite(field + ".theta", pose.theta);
  }
  std::optional<InputProblem> result() const { return problem_; }

 private:
  std::optional<InputProblem> problem_;
};

}  // namespace

std::optional<InputProblem> input_problem(const WorldState& msg) {
  ProblemFinder check;
  check.finite("header.stamp", msg.header.stamp.toSec());
  check.at_most("humans (count)", msg.humans.size(), world::kMaxHumans);
  if (msg.has_ari) {
    check.pose("ari.pose", msg.ari.pose);
    check.finite("ari.linear_velocity", msg.ari.linear_velocity);
    check.finite("ari.angular_velocity", msg.ari.angular_velocity);
    check.finite("ari.head_pan", msg.ari.head_pan);
    check.finite("ari.head_pan_velocity", msg.ari.head_pan_velocity);
  }
  for (size_t i = 0; i < msg.humans.size(); ++i) {
    const HumanState& h = msg.humans[i];
    const std::string field = "humans[" + std::to_string(i) + "]";
    check.pose(field + ".pose", h.pose);
    check.finite(field + ".velocity.linear.x", h.velocity.linear.x);
    check.finite(field + ".velocity.linear.y", h.velocity.linear.y);
    check.finite(field + ".velocity.angular.z", h.velocity.angular.z);
    check.finite(field + ".age", h.age);
    check.one_of(field + ".gender", h.gender, HumanState::GENDER_FEMALE,
                 HumanState::GENDER_NON_IDENTIFIED);
    check.one_of(field + ".emotion", h.emotion, HumanState::EMOTION_NEUTRAL,
                 HumanState::EMOTION_DISTURBED);
    check.one_of(field + ".motion_mode", h.motion_mode, HumanState::MOTION_IDLE,
                 HumanState::MOTION_GROUP);
    if (h.has_goal) {
      check.pose(field + ".goal", h.goal);
    }
    check.finite(field + ".gaze.direction", h.gaze.direction);
    bool known_reaction = h.reaction.empty();
    for (const auto& choice : world::kReactionProfiles) {
      known_reaction = known_reaction || h.reaction == choice.name;
    }
    check.that(known_reaction, field + ".reaction",
               "'" + h.reaction + "', not one of " + core::choice_names(world::kReactionProfiles));
    check.one_of(field + ".posture", h.posture, HumanState::POSTURE_UNSET,
                 HumanState::POSTURE_SITTING);
    check.that(h.posture_progress >= 0.0f && h.posture_progress <= 1.0f,
               field + ".posture_progress",
               core::number_text(h.posture_progress) + ", not in [0, 1]");
    check.that(h.walked_distance >= 0.0 && std::isfinite(h.walked_distance),
               field + ".walked_distance",
               core::number_text(h.walked_distance) + ", not a finite distance of 0 m or more");
  }
  for (size_t i = 0; i < msg.groups.size(); ++i) {
    const std::string field = "groups[" + std::to_string(i) + "]";
    check.finite(field + ".centre.x", msg.groups[i].centre.x);
    check.finite(field + ".centre.y", msg.groups[i].centre.y);
    check.finite(field + ".ospace_radius", msg.groups[i].ospace_radius);
    check.finite(field + ".heading", msg.groups[i].heading);
    check.finite(field + ".utterance_end", msg.groups[i].utterance_end);
    check.that(
        core::names_a_choice(msg.groups[i].arrangement, model::kArrangements),
        field + ".arrangement",
        "'" + msg.groups[i].arrangement + "', not " + core::choice_names(model::kArrangements));
  }
  for (size_t i = 0; i < msg.walking_groups.size(); ++i) {
    const WalkingGroupState& w = msg.walking_groups[i];
    const std::string field = "walking_groups[" + std::to_string(i) + "]";
    check.finite(field + ".leader.x", w.leader.x);
    check.finite(field + ".leader.y", w.leader.y);
    check.finite(field + ".heading", w.heading);
    check.pose(field + ".goal", w.goal);
    check.that(core::names_a_choice(w.formation, world::kWalkingFormations), field + ".formation",
               "'" + w.formation + "', not " + core::choice_names(world::kWalkingFormations));
    check.that(core::names_a_choice(w.on_arrival, world::kArrivalActions), field + ".on_arrival",
               "'" + w.on_arrival + "', not " + core::choice_names(world::kArrivalActions));
  }
  return check.result();
}

std::optional<InputProblem> input_problem(const nav_msgs::OccupancyGrid& msg) {
  ProblemFinder check;
  check.finite("info.resolution", msg.info.resolution);
  check.that(msg.info.resolution > 0.0f, "info.resolution",
             std::to_string(msg.info.resolution) + ", not > 0");
  check.finite("info.origin.position.x", msg.info.origin.position.x);
  check.finite("info.origin.position.y", msg.info.origin.position.y);
  const uint64_t cells = static_cast<uint64_t>(msg.info.width) * msg.info.height;
  check.at_most("info.width x info.height", cells, world::kMaxMapCells);
  check.that(msg.data.size() == cells, "data",
             std::to_string(msg.data.size()) + " cells for a " + std::to_string(msg.info.width) +
                 " x " + std::to_string(msg.info.height) + " grid");
  return check.result();
}

}  // namespace ari_social_sim::nodes
