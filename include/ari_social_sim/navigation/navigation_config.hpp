#pragma once

#include <cstdint>
#include <string>

#include "ari_social_sim/core/yaml_map.hpp"
#include "ari_social_sim/model/ari_limits.hpp"
#include "ari_social_sim/navigation/geodesic_field.hpp"
#include "ari_social_sim/navigation/scene_tracker.hpp"
#include "ari_social_sim/navigation/social_spaces.hpp"

namespace ari_social_sim::navigation {

/// Which optimiser minimises the MPC cost (docs/navigation.md compares them).
enum class SolverKind { kLbfgs, kSlsqp, kMppi };

/// Weights of the cost terms (docs/navigation.md section 3 gives each term's formula and unit).
/// A weight of 0 switches its term off; the non-social baseline sets the social ones to 0.
struct CostWeights {
  double goal{1.0};                  // per step, per m of geodesic distance to the goal (Huber)
  double terminal{10.0};             // the same at the end of the horizon
  double heading{5.0};               // (1 - cos) of the last step's heading off the goal's, at it
  double path_heading{3.0};          // (1 - cos) of the last step's heading off the path direction
  double obstacle{400.0};            // per m^2 of footprint circle inside the obstacle margin
  double agent_clearance{400.0};     // per m^2 of footprint circle inside a person's body margin
  double personal_space{3.0};        // per unit of asymmetric Gaussian at ARI's body edge
  double personal_space_edge{50.0};  // per squared sigma^2/2 of depth inside a personal space
  double group_space{3.0};           // per unit of o-space Gaussian at ARI's body edge
  double ospace_edge{200.0};         // per m^2 of footprint inside a group's o-space disc
  double effort_linear{0.05};        // per (m/s)^2
  double effort_angular{0.05};       // per (rad/s)^2
  double effort_pan{0.01};           // per (rad/s)^2
  double smooth_linear{2.0};         // per (m/s)^2 of change between steps
  double smooth_angular{0.5};        // per (rad/s)^2 of change between steps
  double smooth_pan{0.05};           // per (rad/s)^2 of change between steps
  double acceleration{200.0};        // per (m/s)^2 or (rad/s)^2 of change beyond ARI's limits
  double reverse{30.0};              // per (m/s)^2 of backward speed
  double view{1.0};                  // (1 - cos) of the target's bearing off the head camera axis
  double pan_limit{100.0};           // per rad^2 of pan beyond +-75 deg

  void read(const core::YamlMap& map);
};

/// The model predictive controller (docs/navigation.md).
struct MpcConfig {
  int horizon_steps{20};        // N
  double step_s{0.15};          // dt; N dt = 3 s look-ahead
  double max_linear_mps{0.8};   // social speed cap, at most ARI's 1.0 m/s
  double min_linear_mps{-0.1};  // at least ARI's -0.2 m/s
  double max_angular_rps{1.5};  // at most ARI's 2.094 rad/s
  SolverKind solver{SolverKind::kLbfgs};
  int max_evaluations{60};  // cost evaluations per solve (gradient solvers)
  int mppi_samples{128};
  int mppi_iterations{2};
  double mppi_temperature{0.5};              // lambda, in cost units
  double mppi_noise_linear{0.25};            // m/s, standard deviation of the sampled perturbation
  double mppi_noise_angular{0.6};            // rad/s
  double mppi_noise_pan{0.6};                // rad/s
  uint64_t seed{1};                          // MPPI's sample stream
  int footprint_circles{3};                  // circles covering ARI's footprint
  double obstacle_margin_m{0.05};            // extra clearance from walls and furniture
  double agent_margin_m{0.05};               // extra clearance from people's bodies
  double ospace_margin_m{0.1};               // extra clearance from other groups' o-space disc
  double personal_space_margin_sigmas{0.2};  // personal spaces' stiff edge, beyond their boundary
  double goal_huber_m{0.2};                  // the progress cost is quadratic below, linear above
  double heading_radius_m{0.2};     // the arrival heading counts within about this distance
  double target_space_scale{0.3};   // personal-space weight of the person or group approached...
  double target_space_fade_m{2.5};  // ... fading from this distance to the goal to 0 at half of it
  CostWeights weights;
  PersonalSpaceParams personal_space;
  model::AriLimits limits;  // ARI's own limits (not read from files)

  int control_count() const { return horizon_steps * 3; }
  void read(const core::YamlMap& map);
};

/// Turns "approach a person" and "join a group" into a pose (docs/navigation.md).
struct GoalFinderConfig {
  double approach_distance_m{1.1};   // base_footprint to the person's centre (Hall: personal edge)
  double approach_max_angle{0.52};   // rad, at most this far off the person's facing direction
  double approach_angle_step{0.13};  // rad between candidate places
  double gap_clearance_m{0.3};       // room to leave on each side of ARI in a group's gap
  double gap_width_tolerance{0.35};  // rad: gaps this much narrower than the widest are as good
  double outside_offset_m{0.2};      // how far outside the circle ARI stands when no gap fits
  double free_margin_m{0.05};        // a goal's footprint keeps this from walls and bodies

  void read(const core::YamlMap& map);
};

/// The control loop around the MPC: rates, tolerances, timeouts.
struct NavigatorConfig {
  double rate_hz{10.0};                // replanning rate
  double goal_tolerance_m{0.15};       // base_footprint within this of the goal
  double yaw_tolerance{0.15};          // rad, heading within this of the goal heading
  double target_lost_timeout_s{5.0};   // abort when the target is unseen this long
  double progress_timeout_s{20.0};     // abort when the path to the goal shrinks by less than
  double progress_distance_m{0.3};     //   this distance within the timeout
  double goal_update_distance_m{0.1};  // recompute the geodesic field when the goal moves more
  double goal_switch_distance_m{0.5};  // a goal moving farther than this at once (another gap)...
  double goal_switch_time_s{1.0};      // ... is followed only once it has held this long
  double patience_s{4.0};              // without progress for this long, personal spaces...
  double patience_halving_s{2.0};      // ... lose half their weight every this many seconds
  GeodesicParams geodesic;

  void read(const core::YamlMap& map);
};

/// Everything config/social_mpc.yaml holds. Sections: mpc, weights, personal_space, goal_finder,
/// controller, geodesic, perception_input; every key optional with the defaults above; unknown
/// keys are errors.
struct NavigationConfig {
  MpcConfig mpc;
  GoalFinderConfig goal_finder;
  NavigatorConfig navigator;
  SceneTrackerConfig scene;

  /// Throws core::ConfigError naming the file, field, value and expected range.
  static NavigationConfig from_yaml(const core::YamlMap& map);
  static NavigationConfig load_file(const std::string& path);
};

const char* solver_name(SolverKind kind);

}  // namespace ari_social_sim::navigation
