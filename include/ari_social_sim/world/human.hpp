#pragma once

#include <optional>
#include <string>

#include "ari_social_sim/model/person_attributes.hpp"
#include "ari_social_sim/model/shape_geometry.hpp"
#include "ari_social_sim/world/gaze_event.hpp"
#include "ari_social_sim/world/gaze_generator.hpp"
#include "ari_social_sim/world/head_nod.hpp"
#include "ari_social_sim/world/object.hpp"
#include "ari_social_sim/world/posture.hpp"
#include "ari_social_sim/world/robot_reaction.hpp"
#include "ari_social_sim/world/speech_generator.hpp"

namespace ari_social_sim::world {

/// Oldest age (years) a human may be given.
constexpr double kMaxAgeYears = 130.0;
/// Fastest turn (rad/s) a direct velocity command may ask of a human: one turn per second, well
/// above a person turning on the spot (about half a turn per second).
constexpr double kMaxHumanTurnRateRps = 6.283185307179586;
/// Widest collision circle (m) a human may be given: wider than anyone's shoulders, and small
/// enough that a person still fits through a door of the worlds.
constexpr double kMaxBodyRadiusM = 1.0;

/// Parameters of a human's movement (D6.4 §3.3: step length, goal distance, personal distance).
struct HumanMotionParams {
  /// m/s under a unit force. D6.4's step length is eta = walking_speed * step, so that motion
  /// does not depend on the step size; a goal force of magnitude 1 walks at this speed.
  double walking_speed_mps{1.0};
  /// m/s; a longer step eta * |f| is shortened to this speed (people do not run to their group).
  double max_speed_mps{1.3};
  /// 1/s; the orientation moves by min(1, gain * step) of the remaining turn each step (eq. 3.4,
  /// 3.12 with the step length of the rotation), a time constant of 1/gain.
  double turn_gain_per_s{4.0};
  /// Delta_G (m): within it the goal force fades and the human turns to the goal orientation.
  double goal_distance_m{0.5};
  /// Delta_p (m): radius of the personal area in which others repel (eq. 3.6).
  double personal_distance_m{0.8};
  /// m, radius of the body's collision circle.
  double body_radius_m{0.2};

  template <class V>
  void visit(V& v) {
    v.field("walking_speed", walking_speed_mps,
            "m/s under a unit force (the step length eta is walking_speed x step)",
            core::positive());
    v.field("max_speed", max_speed_mps, "m/s; longer steps are shortened to it", core::positive());
    v.field("turn_gain", turn_gain_per_s,
            "1/s; each step turns min(1, turn_gain x step) of the remaining turn",
            core::positive());
    v.field("goal_distance", goal_distance_m,
            "m (Delta_G): within it the goal force fades and the human turns to the goal's "
            "orientation",
            core::positive());
    v.field("personal_distance", personal_distance_m,
            "m (Delta_p): others within it repel the human", core::positive());
    v.field("body_radius", body_radius_m,
            "m, radius of the body's collision circle (at least Box2D's slop)",
            core::between(model::kMinShapeFeatureM, kMaxBodyRadiusM));
  }
};

/// Everything needed to create a human. Defaults are the documented ones of docs/world.md.
struct HumanSpec {
  model::ObjectId id{model::kNoObject};
  std::string name;
  std::string role;
  core::Pose2 pose;
  double age_years{40.0};
  model::Gender gender{model::Gender::kNonIdentified};
  bool mask{false};
  model::Emotion emotion{model::Emotion::kNeutral};
  HumanMotionParams motion;
  double words_per_minute{150.0};
  std::optional<GazeModel> gaze;
  /// When set, the human walks there with HumanNavigation from the start.
  std::optional<core::Pose2> goal;
  /// How the human reacts to ARI (robot_reaction.hpp); kIgnore: as if ARI were anyone else.
  ReactionProfile reaction{ReactionProfile::kIgnore};
  /// The reaction's distances, times and shares; none: ReactionParams' defaults.
  std::optional<ReactionParams> reaction_params;
  /// Sitting: on a seat centred at `pose`, facing its orientation, from the start (settled).
  Posture posture{Posture::kStanding};

  /// A human as a scene file's `humans` entry writes it (config_fields.hpp).
  template <class V>
  void visit(V& v) {
    v.field(core::required("id"), id, "the human's object id, unique in the world",
            core::positive());
    v.field("name", name, "shown in rviz and reports");
    v.field("role", role, "the human's part in a dialogue (users.roles of the dialogue settings)");
    pose.visit(v);
    v.field("age", age_years, "years", core::between(0.0, kMaxAgeYears));
    v.choice("gender", gender, "as perception reports it", model::kGenders);
    v.field("mask", mask, "wears a face mask");
    v.choice("emotion", emotion, "the displayed expression", model::kEmotions);
    v.field("words_per_minute", words_per_minute, "speaking rate", core::positive());
    v.section("motion", motion, "social-force movement (docs/world.md)");
    v.section("goal", goal, "a pose (position, orientation) the human walks to from the start");
    v.section("gaze", gaze, "where the human looks: targets or directions");
    v.choice("reaction", reaction, "how the human reacts to ARI (docs/world.md, section 10)",
             kReactionProfiles);
    v.section("reaction_params", reaction_params,
              "distances, times and gaze shares of the reaction to ARI");
    v.choice("posture", posture,
             "sitting: on a seat centred at position, facing orientation (docs/world.md)",
             kPostures);
  }

  /// Throws core::RequestError naming the first field outside what visit allows, its value and
  /// the expectation (id 0, a non-finite pose, age outside [0, 130], a rate that is not > 0, an
  /// invalid gaze model, ...). Whether the pose and goal lie on the floor is the simulation's check
  /// (Simulation::add_human).
  void validate() const;
};

/// How a human's movement is driven (D6.4 §3.3.1).
enum class MotionMode : uint8_t { kIdle = 0, kDirect = 1, kNavigation = 2, kGroup = 3 };

class HumanNavigation;

/// A simulated person (D6.4 §3.3). Position comes from its Box2D circle; orientation is kept here
/// (the body does not rotate) and changed only by the movement model.
class Human : public Object {
 public:
  /// `gaze_rng` and `reaction_rng` are the human's own streams (Simulation derives them from its
  /// seed and the id).
  Human(const HumanSpec& spec, core::Rng gaze_rng, core::Rng reaction_rng);

  const HumanSpec& spec() const { return spec_; }
  MotionMode motion_mode() const { return mode_; }

  /// Direct velocity (map frame), held until another command, from when a seated human has stood
  /// up. Expects finite numbers: requests are checked by Simulation::set_human_velocity.
  void set_velocity(const Eigen::Vector2d& velocity_mps, double angular_velocity_rps);
  /// Walks to a goal with HumanNavigation (eq. 3.1-3.7), standing up first if seated. Expects a
  /// finite pose: requests are checked by Simulation::set_human_goal.
  void set_goal(const core::Pose2& goal);
  /// Stands still.
  void stop();
  /// Stands up or sits down (posture.hpp): until standing and settled the human does not move
  /// but for the change itself and keeps its heading; gaze, speech and groups carry on.
  void change_posture(Posture target) { posture_.change_to(target); }
  const PostureState& posture() const { return posture_; }
  /// Hands the movement to a GroupNavigation script (called by the script).
  void join_group(model::ObjectId group_id);
  /// Called by the group script when the human leaves it.
  void leave_group();
  model::ObjectId group_id() const { return group_id_; }

  /// The movement planned for the next step by the navigation component or the group script:
  /// a velocity (m/s, map frame) and a rotation (rad) to apply over the step.
  void plan_motion(const Eigen::Vector2d& velocity_mps, double rotation_rad);
  /// Sets the orientation directly (pose commands).
  void set_orientation(double theta_rad);

  const std::optional<core::Pose2>& goal() const;
  SpeechGenerator& speech() { return *speech_; }
  const SpeechGenerator& speech() const { return *speech_; }
  GazeGenerator* gaze() { return gaze_; }
  const GazeGenerator* gaze() const { return gaze_; }
  /// Installs or replaces the gaze model. Expects a valid model: requests are checked by
  /// Simulation::set_human_gaze.
  void set_gaze_model(GazeModel model);
  /// The gaze the conversation of the human's group gives it while the group talks (none: the
  /// human's own gaze model, which idles meanwhile: its draws would be overridden). Set by
  /// GroupConversation.
  void set_conversation_gaze(const std::optional<GazeEvent>& gaze);
  const std::optional<GazeEvent>& conversation_gaze() const { return conversation_gaze_; }
  /// Nods (a listener's backchannel, GroupConversation); a new nod replaces one under way.
  void nod(const HeadNod& nod) { nod_ = nod; }
  /// The head's pitch (rad, positive: down) at sim time `time_s`: level but while nodding.
  double head_pitch_rad(double time_s) const { return nod_ ? nod_->pitch_at(time_s) : 0.0; }
  /// Sets the reaction to ARI, keeping the spec's reaction parameters: the first profile other
  /// than kIgnore installs a RobotReaction (after the other components, so it sees navigation's
  /// plan), kIgnore makes it inert. Requests are checked by Simulation::set_human_reaction.
  void set_reaction(ReactionProfile profile);
  ReactionProfile reaction_profile() const { return spec_.reaction; }
  /// Null until a profile other than kIgnore was set.
  const RobotReaction* reaction() const { return reaction_; }

  /// How far the human has walked on foot since entering the world (not while seated or changing
  /// posture): every camera's figure of them takes its gait phase from it, so that a reader of
  /// the images (hri_perception_node's crops) poses them as drawn.
  double walked_m() const { return walked_m_; }

  void apply_motion(const StepContext& context) override;
  void sync_from_body(double dt_s) override;

 private:
  // Holds a human who is not standing still against any push (a kinematic body), but for the
  // change of posture under way; lets a standing one be moved by its plan and its contacts.
  void apply_posture(double dt_s);
  // The reaction's velocity and turn in place of, or on top of, what was planned.
  void apply_reaction(const ReactionMotion& reaction, double dt_s, Eigen::Vector2d& velocity,
                      double& rotation) const;

  HumanSpec spec_;
  MotionMode mode_{MotionMode::kIdle};
  model::ObjectId group_id_{model::kNoObject};
  Eigen::Vector2d direct_velocity_{Eigen::Vector2d::Zero()};
  double direct_angular_velocity_{0.0};
  Eigen::Vector2d planned_velocity_{Eigen::Vector2d::Zero()};
  double planned_rotation_{0.0};
  core::Rng gaze_rng_;
  core::Rng reaction_rng_;
  HumanNavigation* navigation_{nullptr};
  RobotReaction* reaction_{nullptr};
  SpeechGenerator* speech_{nullptr};
  GazeGenerator* gaze_{nullptr};
  std::optional<GazeEvent> conversation_gaze_;
  std::optional<HeadNod> nod_;
  PostureState posture_;
  double walked_m_{0.0};
};

}  // namespace ari_social_sim::world
