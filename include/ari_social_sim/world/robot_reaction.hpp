#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>

#include "ari_social_sim/core/config_fields.hpp"
#include "ari_social_sim/core/number_text.hpp"
#include "ari_social_sim/core/pose2.hpp"
#include "ari_social_sim/core/rng.hpp"
#include "ari_social_sim/model/ari_footprint.hpp"
#include "ari_social_sim/world/gaze_event.hpp"
#include "ari_social_sim/world/object.hpp"

namespace ari_social_sim::world {

/// How a person reacts to ARI (issue 17, part 3). One profile per human; kIgnore is the world as
/// it always was (no component, no draw, the same trajectories for the same seed).
enum class ReactionProfile : uint8_t {
  kIgnore = 0,
  kYield = 1,
  kCurious = 2,
  kAvoid = 3,
  kBlock = 4
};

inline constexpr core::Choice<ReactionProfile> kReactionProfiles[] = {
    {ReactionProfile::kIgnore, "ignore"},
    {ReactionProfile::kYield, "yield"},
    {ReactionProfile::kCurious, "curious"},
    {ReactionProfile::kAvoid, "avoid"},
    {ReactionProfile::kBlock, "block"}};

/// The profile's name as files, services and /sim/world_state spell it.
const char* reaction_name(ReactionProfile profile);

/// Distances, times and probabilities of the reactions (docs/world.md, "Reactions to the robot").
/// Distances to ARI are from the person's centre to the nearest point of ARI's footprint
/// rectangle, so "1.2 m" means 1.2 m from the robot's edge, whichever side faces the person.
struct ReactionParams {
  /// m: ARI this close is noticed (curious, avoid and block act; the gaze shares apply): about
  /// where Hall's public distance (3.6 m) begins, so a robot across a room is noticed.
  double notice_distance_m{4.0};
  /// m/s: ARI faster than this is driving and may need to pass (yield, block).
  double moving_speed_mps{0.05};
  /// s and m: the corridor ARI needs ahead of its front is corridor_time x speed + corridor_extra
  /// long: 2.75 m at 0.5 m/s, 3.5 m at ARI's top 1 m/s, so 3.5 s or more of warning, enough for a
  /// sidestep of 1-1.5 s.
  double corridor_time_s{1.5};
  double corridor_extra_m{2.0};
  /// m: a person counts as in ARI's way when their centre is within ARI's half width plus this
  /// of ARI's path line (a personal distance, D6.4's 0.8 m), and steps aside to 0.1 m beyond it.
  double corridor_margin_m{0.8};
  /// m: ARI's rear this far beyond a yielding person (and its outline this far from them) has
  /// passed; the person then goes back, or walks on, once ARI is also clear of their place.
  double passed_distance_m{1.0};
  /// s: the longest a yielding person waits for ARI to pass (ARI may have stopped for good).
  double yield_max_wait_s{15.0};
  /// m: where a curious person stops when walking up to ARI (a personal distance); they back off
  /// when ARI comes closer than curious_min_distance.
  double curious_distance_m{1.2};
  double curious_min_distance_m{1.0};
  /// Chance that a curious person walks up to ARI when noticing it, drawn once per encounter.
  double curious_approach_probability{0.7};
  /// m: an avoiding person keeps at least this from ARI, walking away and turning away.
  double avoid_distance_m{2.5};
  /// m: a blocking person stands this far in front of ARI's front edge, on its heading line.
  double block_distance_m{0.9};
  /// m: the most a group member's reaction moves them off where the encounter found them; the
  /// group script pulls them back into their slot.
  double group_offset_m{0.3};
  /// Share of gaze events aimed at ARI while ARI is noticed, per profile.
  double yield_look_share{0.5};
  double curious_look_share{0.85};
  double avoid_look_share{0.05};
  double block_look_share{0.9};
  /// s: mean dwell of one reaction gaze event (exponential, as GazeGenerator's).
  double gaze_mean_duration_s{1.0};

  template <class V>
  void visit(V& v) {
    const core::Bounds distance = core::between(0.0, 20.0);
    const core::Bounds share = core::between(0.0, 1.0);
    v.field("notice_distance", notice_distance_m, "m from ARI's outline at which people notice it",
            {0.0, 20.0, true});
    v.field("moving_speed", moving_speed_mps, "m/s above which ARI counts as driving",
            core::between(0.0, 1.0));
    v.field("corridor_time", corridor_time_s, "s of ARI's speed in the corridor ahead of it",
            core::between(0.0, 10.0));
    v.field("corridor_extra", corridor_extra_m, "m added to the corridor ahead of ARI", distance);
    v.field("corridor_margin", corridor_margin_m,
            "m beside ARI's half width within which a person is in its way", distance);
    v.field("passed_distance", passed_distance_m,
            "m ARI's rear must be past a yielding person before they return", distance);
    v.field("yield_max_wait", yield_max_wait_s, "s a yielding person waits at most",
            {0.0, 600.0, true});
    v.field("curious_distance", curious_distance_m, "m from ARI a curious person walks up to",
            {0.0, 20.0, true});
    v.field("curious_min_distance", curious_min_distance_m,
            "m from ARI inside which a curious person steps back", distance);
    v.rule("curious_min_distance", curious_min_distance_m <= curious_distance_m,
           "a number <= curious_distance (" + core::number_text(curious_distance_m) + ")",
           core::number_text(curious_min_distance_m));
    v.field("curious_approach_probability", curious_approach_probability,
            "chance a curious person walks up to ARI, per encounter", share);
    v.field("avoid_distance", avoid_distance_m, "m an avoiding person keeps from ARI",
            {0.0, 20.0, true});
    v.field("block_distance", block_distance_m, "m in front of ARI's front a blocker stands",
            {0.0, 5.0, true});
    v.field("group_offset", group_offset_m, "m a group member's reaction moves them at most",
            core::between(0.0, 2.0));
    v.field("yield_look_share", yield_look_share, "share of gaze at ARI (yield)", share);
    v.field("curious_look_share", curious_look_share, "share of gaze at ARI (curious)", share);
    v.field("avoid_look_share", avoid_look_share, "share of gaze at ARI (avoid)", share);
    v.field("block_look_share", block_look_share, "share of gaze at ARI (block)", share);
    v.field("gaze_mean_duration", gaze_mean_duration_s, "s, mean dwell of a reaction gaze",
            {0.0, 600.0, true});
  }

  /// Throws core::RequestError naming the first field outside what visit allows.
  void validate() const;
};

/// ARI as a reacting person sees it: its pose (base_footprint), its footprint and its speed along
/// its heading (negative when reversing).
struct RobotView {
  model::ObjectId id{model::kNoObject};
  core::Pose2 pose;
  model::AriFootprint footprint;
  double linear_mps{0.0};

  /// m from `point` to the nearest point of the footprint rectangle; 0 inside it.
  double distance_to(const Eigen::Vector2d& point) const;
  /// The footprint's centre (m, map frame).
  Eigen::Vector2d centre() const { return pose.transform(footprint.centre_local()); }
  /// Unit vector of ARI's direction of travel (its heading, reversed when it reverses).
  Eigen::Vector2d travel_direction() const;
};

/// Where `point` lies relative to ARI's path: `ahead_m` from ARI's leading edge along its
/// direction of travel (negative beside or behind it), `lateral_m` signed from the path's centre
/// line (positive on ARI's left when driving forward).
struct PathOffset {
  double ahead_m{0.0};
  double lateral_m{0.0};
};
PathOffset path_offset(const RobotView& robot, const Eigen::Vector2d& point);

/// True when a person at `point` stands in the corridor ARI is about to drive through: ARI faster
/// than moving_speed, the point within corridor_time x speed + corridor_extra ahead of ARI's
/// leading edge (or beside its body) and within half width + corridor_margin of its path line.
bool in_robot_corridor(const RobotView& robot, const Eigen::Vector2d& point,
                       const ReactionParams& params);

/// What the reaction asks of the human's motion this step (Human::apply_motion applies it).
struct ReactionMotion {
  enum class Kind : uint8_t {
    kNone,     // the human moves as it would without a reaction
    kReplace,  // this velocity instead of navigation's (a person standing or walking alone)
    kAdd,      // this velocity on top of the planned one (group members, walkers avoiding ARI)
  };
  Kind kind{Kind::kNone};
  Eigen::Vector2d velocity_mps{Eigen::Vector2d::Zero()};  // map frame
  /// Heading (rad, map frame) to turn toward at the human's turn gain; none: the planned turn
  /// (kAdd) or no turn (kReplace).
  std::optional<double> face_rad;
};

/// The reaction of one human to ARI, a generator component run after the human's navigation
/// (D6.4 §3.2). Each step it looks at ARI and the human and decides a ReactionMotion and a gaze
/// override:
///   - yield: when in ARI's corridor, steps perpendicular to ARI's path to the side with free floor
///     (probed against walls and furniture), faces ARI and waits until ARI has passed, then walks
///     back to where it stood (or on to its goal, which navigation still holds);
///   - curious: while ARI is noticed, stops, turns to face it, may walk up to curious_distance and
///     stays there, backing off inside curious_min_distance;
///   - avoid: while ARI is closer than avoid_distance, walks away from it (sliding along walls),
///     facing away;
///   - block: while ARI is noticed and moving (or stands), walks to block_distance in front of
///     ARI's front edge on its heading line and faces it.
/// Group members only add a sidestep (yield) or a step away (avoid) bounded by group_offset to the
/// group script's plan, and look; they stay members. Humans driven by a direct velocity do not
/// react. Gaze: while ARI is noticed, each gaze event (exponential dwell, gaze_mean_duration) is
/// at ARI with the profile's look share; avoid's other events look along the body, never at ARI.
/// Draws come from its own stream (the simulation's seed and the human's id), so they shift no
/// other random process. step() never throws.
class RobotReaction : public Component {
 public:
  RobotReaction(ReactionProfile profile, const ReactionParams& params, core::Rng rng);

  ComponentPhase phase() const override { return ComponentPhase::kGenerator; }
  void step(Object& owner, const StepContext& context) override;

  /// Changes the profile; the current encounter ends (a yielding person stops where they are).
  void set_profile(ReactionProfile profile);
  ReactionProfile profile() const { return profile_; }
  const ReactionParams& params() const { return params_; }

  const ReactionMotion& motion() const { return motion_; }
  const std::optional<GazeEvent>& gaze() const { return gaze_; }

  /// What a reaction is doing, for tests and traces.
  enum class Phase : uint8_t { kIdle, kSteppingAside, kWaiting, kReturning, kEngaged };
  Phase phase_state() const { return phase_; }

 private:
  void reset();
  void update_gaze(const Object& owner, const RobotView& robot, double now_s, bool noticed);
  void plan_alone(const Object& owner, const StepContext& context, const RobotView& robot);
  void plan_member(const Object& owner, const RobotView& robot);
  void plan_yield(const Object& owner, const StepContext& context, const RobotView& robot);
  void plan_curious(const Object& owner, const RobotView& robot);
  void plan_avoid(const Object& owner, const StepContext& context, const RobotView& robot);
  void plan_block(const Object& owner, const RobotView& robot);
  // Where the person steps to get out of ARI's corridor: the nearest free place beside the path
  // (probed against walls and furniture), which is on their own side unless that is shut; further
  // along the path if both sides are shut. (Crossing to a roomier far side while the near one is
  // free put more of ARI's pass inside their personal space in the doorway episodes.)
  Eigen::Vector2d aside_target(const Object& owner, const StepContext& context,
                               const RobotView& robot) const;

  ReactionProfile profile_;
  ReactionParams params_;
  core::Rng rng_;
  ReactionMotion motion_;
  std::optional<GazeEvent> gaze_;
  Phase phase_{Phase::kIdle};
  // The encounter: where it found the human, where a yield steps to, since when it waits.
  core::Pose2 origin_;
  Eigen::Vector2d aside_target_{Eigen::Vector2d::Zero()};
  double aside_face_rad_{0.0};
  double waiting_since_s_{0.0};
  bool approaches_{false};
  // Gaze events: the next change (sim time), whether the current one is at ARI.
  std::optional<double> next_gaze_change_s_;
  bool looking_at_robot_{false};
  double gaze_since_s_{0.0};
};

}  // namespace ari_social_sim::world
