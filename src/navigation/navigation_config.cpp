#include "ari_social_sim/navigation/navigation_config.hpp"

namespace ari_social_sim::navigation {
namespace {

// Reads an optional number in place, keeping the default when the key is absent.
void read_number(const core::YamlMap& map, const std::string& key, double& field,
                 const core::Bounds& bounds) {
  field = map.optional<double>(key, field, bounds);
}

void read_int(const core::YamlMap& map, const std::string& key, int& field, int min, int max) {
  field = map.optional<int>(key, field, core::between(min, max));
}

SolverKind parse_solver(const core::YamlMap& map, const std::string& key, SolverKind fallback) {
  if (!map.has(key)) {
    return fallback;
  }
  const std::string name = map.required<std::string>(key);
  for (SolverKind kind : {SolverKind::kLbfgs, SolverKind::kSlsqp, SolverKind::kMppi}) {
    if (name == solver_name(kind)) {
      return kind;
    }
  }
  map.fail(key, "one of lbfgs, slsqp, mppi", "'" + name + "'");
}

}  // namespace

const char* solver_name(SolverKind kind) {
  switch (kind) {
    case SolverKind::kLbfgs:
      return "lbfgs";
    case SolverKind::kSlsqp:
      return "slsqp";
    case SolverKind::kMppi:
      return "mppi";
  }
  return "";
}

void CostWeights::read(const core::YamlMap& map) {
  const core::Bounds w = core::non_negative();
  read_number(map, "goal", goal, core::positive());
  read_number(map, "terminal", terminal, w);
  read_number(map, "heading", heading, w);
  read_number(map, "path_heading", path_heading, w);
  read_number(map, "obstacle", obstacle, w);
  read_number(map, "agent_clearance", agent_clearance, w);
  read_number(map, "personal_space", personal_space, w);
  read_number(map, "personal_space_edge", personal_space_edge, w);
  read_number(map, "group_space", group_space, w);
  read_number(map, "ospace_edge", ospace_edge, w);
  read_number(map, "effort_linear", effort_linear, w);
  read_number(map, "effort_angular", effort_angular, w);
  read_number(map, "effort_pan", effort_pan, w);
  read_number(map, "smooth_linear", smooth_linear, w);
  read_number(map, "smooth_angular", smooth_angular, w);
  read_number(map, "smooth_pan", smooth_pan, w);
  read_number(map, "acceleration", acceleration, w);
  read_number(map, "reverse", reverse, w);
  read_number(map, "view", view, w);
  read_number(map, "pan_limit", pan_limit, w);
  map.finish();
}

void MpcConfig::read(const core::YamlMap& map) {
  read_int(map, "horizon_steps", horizon_steps, 5, 100);
  read_number(map, "step", step_s, core::between(0.02, 0.5));
  read_number(map, "max_linear_speed", max_linear_mps, {0.0, limits.max_linear_mps, true});
  read_number(map, "min_linear_speed", min_linear_mps, core::between(limits.min_linear_mps, 0.0));
  read_number(map, "max_angular_speed", max_angular_rps, {0.0, limits.max_angular_rps, true});
  solver = parse_solver(map, "solver", solver);
  read_int(map, "max_evaluations", max_evaluations, 2, 100000);
  read_int(map, "mppi_samples", mppi_samples, 2, 100000);
  read_int(map, "mppi_iterations", mppi_iterations, 1, 100);
  read_number(map, "mppi_temperature", mppi_temperature, core::positive());
  read_number(map, "mppi_noise_linear", mppi_noise_linear, core::non_negative());
  read_number(map, "mppi_noise_angular", mppi_noise_angular, core::non_negative());
  read_number(map, "mppi_noise_pan", mppi_noise_pan, core::non_negative());
  seed = map.optional<unsigned>("seed", static_cast<unsigned>(seed));
  read_int(map, "footprint_circles", footprint_circles, 1, 8);
  read_number(map, "obstacle_margin", obstacle_margin_m, core::between(0.0, 1.0));
  read_number(map, "agent_margin", agent_margin_m, core::between(0.0, 1.0));
  read_number(map, "ospace_margin", ospace_margin_m, core::between(0.0, 1.0));
  read_number(map, "personal_space_margin", personal_space_margin_sigmas, core::between(0.0, 2.0));
  read_number(map, "goal_huber", goal_huber_m, {0.0, 10.0, true});
  read_number(map, "heading_radius", heading_radius_m, {0.0, 10.0, true});
  read_number(map, "target_space_scale", target_space_scale, core::between(0.0, 1.0));
  read_number(map, "target_space_fade", target_space_fade_m, core::positive());
  map.finish();
}

void GoalFinderConfig::read(const core::YamlMap& map) {
  read_number(map, "approach_distance", approach_distance_m, core::between(0.5, 3.0));
  read_number(map, "approach_max_angle", approach_max_angle, core::between(0.0, 1.57));
  read_number(map, "approach_angle_step", approach_angle_step, {0.0, 1.57, true});
  read_number(map, "gap_clearance", gap_clearance_m, core::between(0.0, 1.0));
  read_number(map, "gap_width_tolerance", gap_width_tolerance, core::between(0.0, 3.1416));
  read_number(map, "outside_offset", outside_offset_m, core::between(0.0, 2.0));
  read_number(map, "free_margin", free_margin_m, core::between(0.0, 0.5));
  map.finish();
}

void NavigatorConfig::read(const core::YamlMap& map) {
  read_number(map, "rate", rate_hz, core::between(1.0, 100.0));
  read_number(map, "goal_tolerance", goal_tolerance_m, {0.0, 2.0, true});
  read_number(map, "yaw_tolerance", yaw_tolerance, {0.0, 3.1416, true});
  read_number(map, "target_lost_timeout", target_lost_timeout_s, core::positive());
  read_number(map, "progress_timeout", progress_timeout_s, core::positive());
  read_number(map, "progress_distance", progress_distance_m, core::positive());
  read_number(map, "goal_update_distance", goal_update_distance_m, core::positive());
  read_number(map, "goal_switch_distance", goal_switch_distance_m, core::positive());
  read_number(map, "goal_switch_time", goal_switch_time_s, core::non_negative());
  read_number(map, "patience", patience_s, core::positive());
  read_number(map, "patience_halving", patience_halving_s, core::positive());
  map.finish();
}

NavigationConfig NavigationConfig::from_yaml(const core::YamlMap& map) {
  NavigationConfig config;
  if (map.has("mpc")) {
    config.mpc.read(map.map("mpc"));
  }
  if (map.has("weights")) {
    config.mpc.weights.read(map.map("weights"));
  }
  if (map.has("personal_space")) {
    const core::YamlMap space = map.map("personal_space");
    PersonalSpaceParams& p = config.mpc.personal_space;
    read_number(space, "sigma_front", p.sigma_front_m, core::positive());
    read_number(space, "sigma_side", p.sigma_side_m, core::positive());
    read_number(space, "sigma_rear", p.sigma_rear_m, core::positive());
    read_number(space, "front_per_speed", p.front_per_speed_s, core::non_negative());
    read_number(space, "boundary_sigmas", p.boundary_sigmas, {0.0, 5.0, true});
    read_number(space, "person_radius", p.person_radius_m, {0.0, 1.0, true});
    space.finish();
  }
  if (map.has("goal_finder")) {
    config.goal_finder.read(map.map("goal_finder"));
  }
  if (map.has("controller")) {
    config.navigator.read(map.map("controller"));
  }
  if (map.has("perception_input")) {
    config.scene.read(map.map("perception_input"));
  }
  if (map.has("geodesic")) {
    const core::YamlMap geo = map.map("geodesic");
    GeodesicParams& g = config.navigator.geodesic;
    read_number(geo, "inscribed_radius", g.inscribed_radius_m, {0.0, 2.0, true});
    read_number(geo, "preferred_clearance", g.preferred_clearance_m, {0.0, 5.0, true});
    read_number(geo, "clearance_penalty", g.clearance_penalty, core::non_negative());
    read_number(geo, "blocked_cost", g.blocked_cost, {1.0, 1e6, false});
    read_number(geo, "snap_radius", g.snap_radius_m, core::between(0.0, 2.0));
    read_number(geo, "person_clearance", g.person_clearance_m, core::between(0.0, 2.0));
    read_number(geo, "person_cost", g.person_cost, core::non_negative());
    read_number(geo, "group_cost", g.group_cost, core::non_negative());
    geo.finish();
    if (g.preferred_clearance_m < g.inscribed_radius_m) {
      geo.fail("preferred_clearance",
               "a value >= inscribed_radius (" + std::to_string(g.inscribed_radius_m) + ")",
               std::to_string(g.preferred_clearance_m));
    }
  }
  map.finish();
  return config;
}

NavigationConfig NavigationConfig::load_file(const std::string& path) {
  return from_yaml(core::YamlMap::load_file(path));
}

}  // namespace ari_social_sim::navigation
