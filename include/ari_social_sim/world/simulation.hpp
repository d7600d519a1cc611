#pragma once

#include <Eigen/Core>
#include <memory>
#include <unordered_map>
#include <vector>

#include "ari_social_sim/core/config_fields.hpp"
#include "ari_social_sim/model/occupancy_grid.hpp"
#include "ari_social_sim/model/world_description.hpp"
#include "ari_social_sim/world/agent_grid.hpp"
#include "ari_social_sim/world/ari.hpp"
#include "ari_social_sim/world/group_navigation.hpp"
#include "ari_social_sim/world/human.hpp"
#include "ari_social_sim/world/script.hpp"

class b2World;
class b2Shape;

namespace ari_social_sim::world {

/// Most humans one world may hold (spawn requests beyond it are refused; scene files likewise).
constexpr size_t kMaxHumans = 1000;

struct SimulationConfig {
  double step_s{0.05};
  uint64_t seed{0};  // every random draw of the run derives from it; a scene brings its own
  double map_resolution_m{0.05};

  /// The fields world_node takes as parameters (config_fields.hpp); the seed is the scene's.
  template <class V>
  void visit(V& v) {
    v.field("step", step_s, "sim seconds per step", core::Bounds{0.0, 1.0, true});
    v.field("map_resolution", map_resolution_m, "m per cell of /map and of ARI's map sensor",
            model::kMapResolutionBounds);
  }

  /// Throws core::ConfigError naming the field outside the bounds visit gives.
  void validate() const;
};

/// Numeric trouble and silently-corrected input met while stepping, counted rather than thrown.
struct StepDiagnostics {
  uint64_t clamped_commands{0};  // ARI twist or pan commands beyond ARI's limits
};

/// The 2D multi-party world (seed 3.2): Objects with Components, Scripts and Processes on a Box2D
/// world. Each step runs, in the seed's order: the objects' generator components (navigation,
/// gaze, speech, ARI's drive) and their planned motion, the physics step, the sensor components,
/// then the scripts (group navigation) and the processes.
///
/// Requests (add, remove, commands) validate their input and throw core::RequestError; step()
/// never throws. Every number a request brings is checked before anything changes, so a refused
/// request leaves the world as it was: positions and centres finite and on the floor, headings
/// finite (within +-kMaxHeadingRad), speeds, radii, durations and probabilities finite and in
/// their documented ranges. Refusals name the request (world_node's service), the field, the value
/// and the expectation, e.g.
///   `set_goal: goal.x: expected a finite number inside the world [-0.2, 12.2], got nan`.
class Simulation {
 public:
  /// Throws core::ConfigError for an invalid config or world (model::WorldDescription::validate),
  /// or a world whose occupancy grid would exceed kMaxMapCells at config.map_resolution_m.
  Simulation(model::WorldDescription world, SimulationConfig config);
  ~Simulation();
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  /// Adds a human (world_node's /sim/spawn_human). Throws if the spec is invalid
  /// (HumanSpec::validate), its position or goal is off the floor, the id is taken, the world
  /// already holds kMaxHumans humans, or the body would stand outside the floor or overlap a wall,
  /// furniture, ARI or another human.
  Human& add_human(const HumanSpec& spec);
  void remove_human(model::ObjectId id);
  /// Adds ARI (at most one). Same checks as add_human.
  Ari& add_ari(const AriSpec& spec);
  /// Creates a group of existing humans, each leaving any previous group (/sim/create_group).
  /// Throws if the spec is invalid (GroupSpec::validate), its centre is off the floor, the id is
  /// taken or a member does not exist.
  GroupNavigation& add_group(const GroupSpec& spec);
  /// Moves existing humans into a group (/sim/add_group_members). Throws for an unknown group or
  /// human, or when the group would have more than kMaxGroupMembers members.
  void add_group_members(model::ObjectId group_id, const std::vector<model::ObjectId>& members);
  void remove_group(model::ObjectId group_id);
  /// Takes a human out of its group (if any) so a goal, velocity or pose command can drive it.
  void release_from_group(model::ObjectId human_id);
  /// Sends a human walking to a goal with HumanNavigation, out of its group (world_node's
  /// /sim/set_goal). Throws for an unknown id or a goal off the floor or with a non-finite heading.
  void set_human_goal(model::ObjectId human_id, const core::Pose2& goal);
  /// Gives a human a constant velocity (m/s, map frame) and turn rate (rad/s), out of its group
  /// (/sim/set_velocity). Throws for an unknown id, a non-finite number, a speed above the
  /// human's max_speed or a turn rate beyond +-kMaxHumanTurnRateRps.
  void set_human_velocity(model::ObjectId human_id, const Eigen::Vector2d& velocity_mps,
                          double angular_velocity_rps);
  /// Installs or replaces a human's gaze model (/sim/set_gaze_targets). Throws for an unknown id,
  /// an invalid model (GazeModel::validate), or a target that is not another object of the world.
  void set_human_gaze(model::ObjectId human_id, const GazeModel& model);
  /// Moves a group's o-space centre (/sim/set_group_centre). Throws for an unknown group or a
  /// centre off the floor.
  void set_group_centre(model::ObjectId group_id, const Eigen::Vector2d& centre);
  /// The speech generator of ARI or of a human, by id; throws for any other id.
  SpeechGenerator& speech_of(model::ObjectId speaker_id);
  /// Places a human or ARI directly (/sim/set_pose); a human leaves its group. Throws for an
  /// unknown id, a pose off the floor or with a non-finite heading, or one that overlaps anything.
  void set_pose(model::ObjectId id, const core::Pose2& pose);
  void add_process(std::unique_ptr<Process> process);
  /// ARI's base twist (seed 3.5.5), held for ARI's command timeout. Finite out-of-limit values
  /// are clamped as ARI's controller does and counted in diagnostics(). Throws without ARI or for
  /// a non-finite value (the command is then ignored).
  void command_ari_twist(double linear_mps, double angular_rps);
  /// ARI's head pan target (rad) or velocity (rad/s); clamped, counted and refused likewise.
  void command_ari_head_pan(double pan_rad);
  void command_ari_head_pan_velocity(double pan_velocity_rps);
  /// 3D mode: ARI's base follows this pose and twist from the 3D simulation (Ari::follow).
  /// Throws without ARI or for a non-finite value.
  void follow_ari(const core::Pose2& pose, double linear_mps, double angular_rps);
  /// Smallest id >= `from` that no object uses.
  model::ObjectId next_free_id(model::ObjectId from) const;

  void step();

  double time_s() const { return static_cast<double>(step_count_) * config_.step_s; }
  uint64_t step_count() const { return step_count_; }
  const SimulationConfig& config() const { return config_; }
  const model::WorldDescription& world() const { return world_; }
  const StepDiagnostics& diagnostics() const { return diagnostics_; }

  Object* find_object(model::ObjectId id) const;
  Human* find_human(model::ObjectId id) const;
  GroupNavigation* find_group(model::ObjectId id) const;
  Ari* ari() const { return ari_.get(); }
  /// Humans ordered by id.
  const std::vector<std::unique_ptr<Human>>& humans() const { return humans_; }
  /// Groups ordered by id.
  const std::vector<std::unique_ptr<GroupNavigation>>& groups() const { return groups_; }

  /// Fills `out` with the centres of agents (humans and ARI) closer than `radius_m` to `point`,
  /// except `exclude` and members of group `exclude_group`, in a deterministic order.
  void agent_centres_near(const Eigen::Vector2d& point, double radius_m, const Object* exclude,
                          std::vector<Eigen::Vector2d>& out,
                          model::ObjectId exclude_group = model::kNoObject) const;
  /// How deep (m) an agent's body reaches into walls or furniture; <= 0 when clear.
  double static_penetration_m(const Object& agent) const;

 private:
  void check_placement(const b2Shape& shape, const core::Pose2& pose, const Object* ignore,
                       const std::string& what) const;
  void add_floor_fence();
  void register_object(Object& object);
  /// The human with this id; throws core::RequestError if there is none.
  Human& existing_human(model::ObjectId human_id) const;
  /// Marks the neighbour grid out of date: call whenever an agent moves, appears or disappears.
  void agents_changed() { agent_grid_stale_ = true; }

  model::WorldDescription world_;
  SimulationConfig config_;
  std::unique_ptr<b2World> physics_;
  std::vector<std::unique_ptr<Object>> statics_;
  std::vector<std::unique_ptr<Human>> humans_;
  std::unique_ptr<Ari> ari_;
  std::vector<std::unique_ptr<GroupNavigation>> groups_;
  std::vector<std::unique_ptr<Process>> processes_;
  std::unordered_map<model::ObjectId, Object*> objects_by_id_;
  uint64_t step_count_{0};
  StepDiagnostics diagnostics_;
  // Rebuilt lazily by the first neighbour query after agents changed; a cache, hence mutable.
  mutable AgentGrid agent_grid_;
  mutable bool agent_grid_stale_{true};
};

}  // namespace ari_social_sim::world
