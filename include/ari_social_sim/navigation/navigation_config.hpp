#pragma once

#include <cstdint>
#include <string>

#include "ari_social_sim/core/config_fields.hpp"
#include "ari_social_sim/core/number_text.hpp"
#include "ari_social_sim/core/yaml_map.hpp"
#include "ari_social_sim/model/ari_limits.hpp"
#include "ari_social_sim/navigation/geodesic_field.hpp"
#include "ari_social_sim/navigation/scene_tracker.hpp"
#include "ari_social_sim/navigation/social_spaces.hpp"

namespace ari_social_sim::navigation {

/// Which optimiser minimises the MPC cost (docs/navigation.md compares them).
enum class SolverKind { kLbfgs, kSlsqp, kMppi };

inline constexpr core::Choice<SolverKind> kSolverNames[] = {
    {SolverKind::kLbfgs, "lbfgs"}, {SolverKind::kSlsqp, "slsqp"}, {SolverKind::kMppi, "mppi"}};

/// Weights of the cost terms (docs/navigation.md section 3 gives each term's formula and unit).
/// A weight of 0 switches its term off; the non-social baseline sets the social ones to 0.
struct CostWeights {
  double goal{1.0};
  double terminal{10.0};
  double heading{5.0};
  double path_heading{3.0};
  double obstacle{400.0};
  double agent_clearance{400.0};
  double personal_space{3.0};
  double personal_space_edge{50.0};
  double group_space{3.0};
  double ospace_edge{200.0};
  double effort_linear{0.05};
  double effort_angular{0.05};
  double effort_pan{0.01};
  double smooth_linear{2.0};
  double smooth_angular{0.5};
  double smooth_pan{0.05};
  double acceleration{200.0};
  double reverse{30.0};
  double view{1.0};
  double pan_limit{100.0};

  template <class V>
  void visit(V& v) {
    const core::Bounds weight = core::non_negative();
    // The goal term alone pulls ARI forward: it cannot be switched off.
    v.field("goal", goal, "per step, per m of geodesic distance to the goal (Huber)",
            core::positive());
    v.field("terminal", terminal, "the same at the end of the horizon", weight);
    v.field("heading", heading, "(1 - cos) of the last step's heading off the goal's, at it",
            weight);
    v.field("path_heading", path_heading,
            "(1 - cos) of the last step's heading off the path direction", weight);
    v.field("obstacle", obstacle, "per m^2 of footprint circle inside the obstacle margin", weight);
    v.field("agent_clearance", agent_clearance,
            "per m^2 of footprint circle inside a person's body margin", weight);
    v.field("personal_space", personal_space, "per unit of asymmetric Gaussian at ARI's body edge",
            weight);
    v.field("personal_space_edge", personal_space_edge,
            "per squared sigma^2/2 of depth inside a personal space", weight);
    v.field("group_space", group_space, "per unit of o-space Gaussian at ARI's body edge", weight);
    v.field("ospace_edge", ospace_edge, "per m^2 of footprint inside a group's o-space disc",
            weight);
    v.field("effort_linear", effort_linear, "per (m/s)^2", weight);
    v.field("effort_angular", effort_angular, "per (rad/s)^2", weight);
    v.field("effort_pan", effort_pan, "per (rad/s)^2 of head pan", weight);
    v.field("smooth_linear", smooth_linear, "per (m/s)^2 of change between steps", weight);
    v.field("smooth_angular", smooth_angular, "per (rad/s)^2 of change between steps", weight);
    v.field("smooth_pan", smooth_pan, "per (rad/s)^2 of head pan change between steps", weight);
    v.field("acceleration", acceleration, "per (m/s)^2 or (rad/s)^2 of change beyond ARI's limits",
            weight);
    v.field("reverse", reverse, "per (m/s)^2 of backward speed", weight);
    v.field("view", view, "(1 - cos) of the target's bearing off the head camera axis", weight);
    v.field("pan_limit", pan_limit, "per rad^2 of pan beyond +-75 deg", weight);
  }
};

/// The model predictive controller (docs/navigation.md).
struct MpcConfig {
  int horizon_steps{20};
  double step_s{0.15};
  double max_linear_mps{0.8};
  double min_linear_mps{-0.1};
  double max_angular_rps{1.5};
  SolverKind solver{SolverKind::kLbfgs};
  int max_evaluations{60};
  int mppi_samples{128};
  int mppi_iterations{2};
  double mppi_temperature{0.5};
  double mppi_noise_linear{0.25};
  double mppi_noise_angular{0.6};
  double mppi_noise_pan{0.6};
  uint64_t seed{1};
  int footprint_circles{3};
  double obstacle_margin_m{0.05};
  double agent_margin_m{0.05};
  double ospace_margin_m{0.1};
  double personal_space_margin_sigmas{0.2};
  double goal_huber_m{0.2};
  double heading_radius_m{0.2};
  double target_space_scale{0.3};
  double target_space_fade_m{2.5};
  CostWeights weights;                 // the file's `weights:` section
  PersonalSpaceParams personal_space;  // the file's `personal_space:` section
  model::AriLimits limits;             // ARI's own limits (not read from files)

  int control_count() const { return horizon_steps * 3; }

  /// The `mpc:` section.
  template <class V>
  void visit(V& v) {
    v.field("horizon_steps", horizon_steps, "N", core::between(5.0, 100.0));
    v.field("step", step_s, "s per step; N x step = 3 s of look-ahead", core::between(0.02, 0.5));
    v.field("max_linear_speed", max_linear_mps, "m/s, social speed cap within ARI's limit",
            core::Bounds{0.0, limits.max_linear_mps, true});
    v.field("min_linear_speed", min_linear_mps, "m/s, backward, within ARI's limit",
            core::between(limits.min_linear_mps, 0.0));
    v.field("max_angular_speed", max_angular_rps, "rad/s, within ARI's limit",
            core::Bounds{0.0, limits.max_angular_rps, true});
    v.choice("solver", solver, "lbfgs or slsqp: NLopt on the analytic gradient; mppi: sampling",
             kSolverNames);
    v.field("max_evaluations", max_evaluations, "cost evaluations per solve (lbfgs, slsqp)",
            core::between(2.0, 100000.0));
    v.field("mppi_samples", mppi_samples, "MPPI's sampled control sequences",
            core::between(2.0, 100000.0));
    v.field("mppi_iterations", mppi_iterations, "MPPI's refinements per solve",
            core::between(1.0, 100.0));
    v.field("mppi_temperature", mppi_temperature, "MPPI's lambda, in cost units", core::positive());
    v.field("mppi_noise_linear", mppi_noise_linear,
            "m/s, standard deviation of the sampled perturbation", core::non_negative());
    v.field("mppi_noise_angular", mppi_noise_angular, "rad/s", core::non_negative());
    v.field("mppi_noise_pan", mppi_noise_pan, "rad/s", core::non_negative());
    v.field("seed", seed, "MPPI's random stream");
    v.field("footprint_circles", footprint_circles, "circles covering ARI's 0.76 x 0.54 m base",
            core::between(1.0, 8.0));
    v.field("obstacle_margin", obstacle_margin_m, "m kept from walls and furniture",
            core::between(0.0, 1.0));
    v.field("agent_margin", agent_margin_m, "m kept from people's bodies", core::between(0.0, 1.0));
    v.field("ospace_margin", ospace_margin_m, "m kept from other groups' o-space disc",
            core::between(0.0, 1.0));
    v.field("personal_space_margin", personal_space_margin_sigmas,
            "sigmas beyond personal spaces' edge where their stiff term starts",
            core::between(0.0, 2.0));
    v.field("goal_huber", goal_huber_m, "m: the progress cost is quadratic below, linear above",
            core::Bounds{0.0, 10.0, true});
    v.field("heading_radius", heading_radius_m,
            "m: the arrival heading counts within about this distance",
            core::Bounds{0.0, 10.0, true});
    v.field("target_space_scale", target_space_scale,
            "personal-space weight of the person approached or the members joined",
            core::between(0.0, 1.0));
    v.field("target_space_fade", target_space_fade_m,
            "m to the goal where that weight starts fading, reaching 0 at half of it",
            core::positive());
  }
};

/// Turns "approach a person" and "join a group" into a pose (docs/navigation.md).
struct GoalFinderConfig {
  double approach_distance_m{1.1};  // Hall: the personal zone's edge
  double approach_max_angle{0.52};
  double approach_angle_step{0.13};
  double gap_clearance_m{0.3};
  double gap_width_tolerance{0.35};
  double outside_offset_m{0.2};
  double free_margin_m{0.05};

  template <class V>
  void visit(V& v) {
    v.field("approach_distance", approach_distance_m,
            "m, base_footprint to the centre of the person approached", core::between(0.5, 3.0));
    v.field("approach_max_angle", approach_max_angle,
            "rad, at most this far off the person's facing direction", core::between(0.0, 1.57));
    v.field("approach_angle_step", approach_angle_step, "rad between candidate places",
            core::Bounds{0.0, 1.57, true});
    v.field("gap_clearance", gap_clearance_m, "m left on each side of ARI in a group's gap",
            core::between(0.0, 1.0));
    v.field("gap_width_tolerance", gap_width_tolerance,
            "rad: gaps this much narrower than the widest count as equally wide",
            core::between(0.0, 3.1416));
    v.field("outside_offset", outside_offset_m,
            "m outside the group's circle where ARI stands when no gap fits",
            core::between(0.0, 2.0));
    v.field("free_margin", free_margin_m, "m a goal's footprint keeps from walls and bodies",
            core::between(0.0, 0.5));
  }
};

/// The control loop around the MPC: rates, tolerances, timeouts.
struct NavigatorConfig {
  double rate_hz{10.0};
  double goal_tolerance_m{0.15};
  double yaw_tolerance{0.15};
  double join_shortfall_tolerance_m{0.1};
  double target_lost_timeout_s{5.0};
  double progress_timeout_s{20.0};
  double progress_distance_m{0.3};
  double goal_update_distance_m{0.1};
  double goal_update_angle{0.1};
  double goal_switch_distance_m{0.5};
  double goal_switch_time_s{1.0};
  double patience_s{4.0};
  double patience_halving_s{2.0};
  std::string policy_file;  // a learned policy driving instead of SocialMPC (docs/learning.md)
  GeodesicParams geodesic;  // the file's `geodesic:` section

  /// The `controller:` section.
  template <class V>
  void visit(V& v) {
    v.field("rate", rate_hz, "Hz of replanning", core::between(1.0, 100.0));
    v.field("goal_tolerance", goal_tolerance_m, "m: arrived when base_footprint is this close",
            core::Bounds{0.0, 2.0, true});
    v.field("yaw_tolerance", yaw_tolerance, "rad: and the heading this close to the goal's",
            core::Bounds{0.0, 3.1416, true});
    v.field("join_shortfall_tolerance", join_shortfall_tolerance_m,
            "m: joining a group, base_footprint also at most this far short of the goal along "
            "its heading (outside the participants' ring)",
            core::between(0.0, 2.0));
    v.rule("join_shortfall_tolerance", join_shortfall_tolerance_m <= goal_tolerance_m,
           "a value <= goal_tolerance (" + core::number_text(goal_tolerance_m) + ")",
           core::number_text(join_shortfall_tolerance_m));
    v.field("target_lost_timeout", target_lost_timeout_s,
            "s: abort when the target is unseen this long", core::positive());
    v.field("progress_timeout", progress_timeout_s,
            "s: abort when the path to the goal shrinks by less than progress_distance within it",
            core::positive());
    v.field("progress_distance", progress_distance_m, "m", core::positive());
    v.field("goal_update_distance", goal_update_distance_m,
            "m: a goal found again moves (and its geodesic field is recomputed) only when it "
            "shifts more, or turns more than goal_update_angle",
            core::positive());
    v.field("goal_update_angle", goal_update_angle, "rad", core::between(0.0, 3.1416));
    v.field("goal_switch_distance", goal_switch_distance_m,
            "m: a goal jumping farther at once (another gap) is followed only once it has held "
            "goal_switch_time",
            core::positive());
    v.field("goal_switch_time", goal_switch_time_s, "s", core::non_negative());
    v.field("patience", patience_s,
            "s without progress before personal spaces give way, losing half their weight every "
            "patience_halving",
            core::positive());
    v.field("patience_halving", patience_halving_s, "s", core::positive());
    v.field("policy_file", policy_file,
            "a trained policy (scripts/train_join_group.py's policy.yaml) that drives ARI instead "
            "of SocialMPC; empty: SocialMPC");
  }
};

/// Everything config/social_mpc.yaml holds, which is also social_mpc_node's private parameters:
/// every key optional with the defaults above; unknown keys are errors.
struct NavigationConfig {
  MpcConfig mpc;
  GoalFinderConfig goal_finder;
  NavigatorConfig navigator;
  SceneTrackerConfig scene;

  /// The file's layout, which groups the structs' fields by what a user tunes together.
  template <class V>
  void visit(V& v) {
    v.section("mpc", mpc, "the model predictive controller over ARI's base and head pan");
    v.section("weights", mpc.weights,
              "weight of each cost term (docs/navigation.md section 3); 0 switches a term off");
    v.section("personal_space", mpc.personal_space,
              "the asymmetric Gaussian around each person; its edge at boundary_sigmas");
    v.section("goal_finder", goal_finder, "where ARI stands to approach a person or join a group");
    v.section("controller", navigator, "replanning rate, arrival and abort rules");
    v.section("geodesic", navigator.geodesic, "the travel-cost field towards the goal");
    v.section("perception_input", scene, "filtering of the perceived people and groups");
  }

  /// Throws core::ConfigError naming the field outside what visit allows.
  void validate() const;
  /// Throws core::ConfigError naming the file, field, value and expected range.
  static NavigationConfig from_yaml(const core::YamlMap& map);
  static NavigationConfig load_file(const std::string& path);
};

/// lbfgs, slsqp or mppi.
const char* solver_name(SolverKind kind);

}  // namespace ari_social_sim::navigation
