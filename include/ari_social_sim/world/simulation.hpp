#pragma once

#include <Eigen/Core>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "ari_social_sim/core/clock_time.hpp"
#include "ari_social_sim/core/config_fields.hpp"
#include "ari_social_sim/core/const_pointer_view.hpp"
#include "ari_social_sim/model/occupancy_grid.hpp"
#include "ari_social_sim/model/world_description.hpp"
#include "ari_social_sim/world/agent_grid.hpp"
#include "ari_social_sim/world/ari.hpp"
#include "ari_social_sim/world/group_conversation.hpp"
#include "ari_social_sim/world/group_navigation.hpp"
#include "ari_social_sim/world/group_turnover.hpp"
#include "ari_social_sim/world/human.hpp"
#include "ari_social_sim/world/request_check.hpp"
#include "ari_social_sim/world/walking_group.hpp"

class b2World;
class b2Shape;

namespace ari_social_sim::world {

/// Most humans one world may hold (spawn requests beyond it are refused; scene files likewise).
constexpr size_t kMaxHumans = 1000;
/// How far (m) a human leaving its group steps back out of the formation.
constexpr double kLeaveStepM = 1.2;
/// The smallest id a human spawned without one gets: smaller ones are left to ARI (1) and to the
/// people of hand-written scenes.
constexpr model::ObjectId kFirstAutomaticHumanId = 10;

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

/// The 2D multi-party world (D6.4 §3.2): Objects with Components, and group scripts, on a Box2D
/// world. Each step runs, in D6.4's order: the objects' generator components (navigation,
/// gaze, speech, ARI's drive) and their planned motion, the physics step, the sensor components,
/// then the scripts (group navigation).
///
/// Its public methods that change the world are the world's whole request API: world_node's
/// services and topics, the in-process engine's commands (scenario::Episode) and scene files all
/// go through them, and every rule of a request lives in them. Readers get const objects only
/// (find_human, humans(), ...). Requests throw core::RequestError; step() never throws. Every
/// number a request brings is checked before anything changes, so a refused request leaves the
/// world as it was: positions and centres finite and on the floor, headings finite (within
/// +-kMaxHeadingRad), speeds, radii, durations and probabilities finite and in their documented
/// ranges. Refusals name the request (world_node's service), the field, the value and the
/// expectation, e.g.
///   `set_goal: goal.x: expected a finite number inside the world [-0.2, 12.2], got nan`.
/// Requests in the shape the services carry them (text, parallel lists) become the core's types
/// through service_requests.hpp.
class Simulation {
 public:
  /// Throws core::ConfigError for an invalid config or world (model::WorldDescription::validate),
  /// or a world whose occupancy grid would exceed kMaxMapCells at config.map_resolution_m.
  Simulation(model::WorldDescription world, SimulationConfig config);
  ~Simulation();
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  /// Adds a human (world_node's /sim/spawn_human). A spec without an id (kNoObject) gets
  /// next_free_id(kFirstAutomaticHumanId). Throws if the spec is invalid (HumanSpec::validate), its
  /// position or goal is off the floor, a gaze target is not another object of the world, the id
  /// is taken or was an object's earlier in the run (ids are never reused, so that a consumer of
  /// the world state or a bag cannot mistake a new person for a removed one), the world already
  /// holds kMaxHumans humans, or the body would stand outside the floor or overlap a wall,
  /// furniture, ARI or another human.
  const Human& add_human(HumanSpec spec);
  /// Takes a human out of the world, and out of its group (/sim/remove_human). Throws for an
  /// unknown id.
  void remove_human(model::ObjectId id);
  /// Adds ARI (at most one). Same checks as add_human.
  const Ari& add_ari(const AriSpec& spec);
  /// Creates a group of existing humans, each leaving any previous group (/sim/create_group). A
  /// spec without an id (kNoObject) gets one past the highest group id (1 for the first group).
  /// Throws if the spec is invalid (GroupSpec::validate), its centre is off the floor, the id is
  /// taken or a member does not exist.
  const GroupNavigation& add_group(GroupSpec spec);
  /// Sends existing humans walking together to a goal (/sim/create_walking_group, docs/world.md
  /// "Walking groups"). Walking and conversation groups share one id space: a spec without an id
  /// gets one past the highest group id of either kind. Members in another group (walking or
  /// conversing) leave it, as create_group's do. Throws if the spec is invalid
  /// (WalkingGroupSpec::validate), its goal is off the floor, the id is taken by a group of either
  /// kind, a member does not exist, the speed exceeds the slowest member's max_speed, or no route
  /// keeping the members' body radius plus kWalkingWallMarginM clear of walls and furniture leads
  /// from the members' centroid to the goal.
  const WalkingGroup& add_walking_group(WalkingGroupSpec spec);
  /// Moves existing humans into a group (/sim/add_group_members). Throws for an unknown group or
  /// human, or when the group would have more than kMaxGroupMembers members.
  void add_group_members(model::ObjectId group_id, const std::vector<model::ObjectId>& members);
  /// Sends a human walking to a goal with HumanNavigation, out of its group (world_node's
  /// /sim/set_goal). Throws for an unknown id or a goal off the floor or with a non-finite heading.
  void set_human_goal(model::ObjectId human_id, const core::Pose2& goal);
  /// Gives a human a constant velocity (m/s, map frame) and turn rate (rad/s), out of its group
  /// (/sim/set_velocity). Throws for an unknown id, a non-finite number, a speed above the
  /// human's max_speed or a turn rate beyond +-kMaxHumanTurnRateRps.
  void set_human_velocity(model::ObjectId human_id, const Eigen::Vector2d& velocity_mps,
                          double angular_velocity_rps);
  /// Sets how a human reacts to ARI (/sim/set_reaction, robot_reaction.hpp), keeping its
  /// reaction parameters. `profile` is a name of kReactionProfiles. Throws for an unknown id, e.g.
  /// `set_reaction: id: no human with id 99`, or an unknown profile, e.g.
  /// `set_reaction: profile: expected ignore, yield, curious, avoid or block, got 'shy'`.
  void set_human_reaction(model::ObjectId human_id, const std::string& profile);
  void set_human_reaction(model::ObjectId human_id, ReactionProfile profile);
  /// Makes a human stand up (kSeatToFeetM forward, over kPostureChangeS) or sit down (as far back,
  /// onto the seat behind them: the world does not check that there is one). Sitting down ends a
  /// walk or a velocity command; a seated member stays in its group. Throws for an unknown id.
  void set_human_posture(model::ObjectId human_id, Posture posture);
  /// Installs or replaces a human's gaze model (/sim/set_gaze_targets). Throws for an unknown id,
  /// an invalid model (GazeModel::validate), or a target that is not another object of the world.
  void set_human_gaze(model::ObjectId human_id, const GazeModel& model);
  /// Gives a group a new arrangement, its rows at `heading_rad` (unset: from where the members
  /// stand) (/sim/set_group_arrangement). Throws for an unknown group or a non-finite heading.
  void set_group_arrangement(model::ObjectId group_id, model::Arrangement arrangement,
                             std::optional<double> heading_rad);
  /// A human or ARI joins a group (/sim/join_group): a human becomes a member (leaving any other
  /// group) and walks to the place the others open; ARI is counted in the formation, so the
  /// members open a place for it, until it leaves. Throws for an unknown group or agent.
  void join_group(model::ObjectId group_id, model::ObjectId agent_id);
  /// A human or ARI leaves its group (/sim/leave_group): a human steps back out of the
  /// formation (kLeaveStepM farther from the centre, if that place is free; otherwise it stands)
  /// and the others close the gap; ARI is no longer counted, nor counted again until it has gone
  /// away. Throws for an unknown agent or one in no group.
  void leave_group(model::ObjectId agent_id);
  /// Switches a group's conversation on or off (/sim/set_group_conversation); on, it talks with the
  /// parameters of its spec's `conversation`. Throws for an unknown group.
  void set_group_conversation(model::ObjectId group_id, bool enabled);
  /// Where conversation groups get their words (conversation_lines.hpp); without it they stay
  /// silent. world_node and the engine install world_speech::SmallTalkLines.
  void set_conversation_lines(std::shared_ptr<const ConversationLines> lines);
  /// Moves a group's o-space centre (/sim/set_group_centre). Throws for an unknown group or a
  /// centre off the floor.
  void set_group_centre(model::ObjectId group_id, const Eigen::Vector2d& centre);
  /// ARI or a human starts saying `content` as speech act `act`, cutting off what it was saying
  /// (/sim/say). Returns the seconds it will take. Throws for an id that is neither ARI nor a
  /// human, or content or act SpeechGenerator::say refuses.
  double say(model::ObjectId speaker_id, const std::string& act, const std::string& content);
  /// Places a human or ARI directly (/sim/set_pose); a human leaves its group. Throws for an
  /// unknown id, a pose off the floor or with a non-finite heading, or one that overlaps anything.
  void set_pose(model::ObjectId id, const core::Pose2& pose);
  /// ARI's base twist (D6.4 §3.5.5), held for ARI's command timeout. Finite out-of-limit values
  /// are clamped as ARI's controller does and counted in diagnostics(). Throws without ARI or for
  /// a non-finite value (the command is then ignored).
  void command_ari_twist(double linear_mps, double angular_rps);
  /// ARI's head pan target (rad) or velocity (rad/s); clamped, counted and refused likewise.
  void command_ari_head_pan(double pan_rad);
  void command_ari_head_pan_velocity(double pan_velocity_rps);
  /// 3D mode: ARI's base follows this pose and twist from the 3D simulation (Ari::follow).
  /// Throws without ARI or for a non-finite value.
  void follow_ari(const core::Pose2& pose, double linear_mps, double angular_rps);
  /// set_human_gaze's rule on its own, for a caller that words the refusal itself (a scene file
  /// names the entry): throws `targets[i]: expected another object of the world, got 7` (after
  /// `check`'s request) unless every target of `model` is an object of the world other than
  /// `human_id`.
  void check_gaze_targets(const RequestCheck& check, model::ObjectId human_id,
                          const GazeModel& model) const;
  /// Smallest id >= `from` (and >= kFirstAutomaticHumanId) that no object of this simulation has
  /// had, removed ones included: automatic ids only increase within a run (a new simulation, as
  /// /sim/reset builds, starts over).
  model::ObjectId next_free_id(model::ObjectId from) const;

  void step();

  double time_s() const { return core::clock_time_s(step_count_, config_.step_s); }
  uint64_t step_count() const { return step_count_; }
  const SimulationConfig& config() const { return config_; }
  const model::WorldDescription& world() const { return world_; }
  const StepDiagnostics& diagnostics() const { return diagnostics_; }

  /// Null when there is no such object (human, ARI, wall or furniture), human or group.
  const Object* find_object(model::ObjectId id) const;
  const Human* find_human(model::ObjectId id) const;
  const GroupNavigation* find_group(model::ObjectId id) const;
  const WalkingGroup* find_walking_group(model::ObjectId id) const;
  /// The conversation of a group; null when the group has none (switched off) or is unknown.
  const GroupConversation* find_conversation(model::ObjectId group_id) const;
  const Ari* ari() const { return ari_.get(); }
  /// Humans ordered by id.
  core::ConstPointerView<Human> humans() const { return core::ConstPointerView<Human>(humans_); }
  /// Groups ordered by id.
  core::ConstPointerView<GroupNavigation> groups() const {
    return core::ConstPointerView<GroupNavigation>(groups_);
  }

  /// Walking groups ordered by id; one arriving with `converse` becomes a conversation group of
  /// the same id (groups()) in the step it arrives.
  core::ConstPointerView<WalkingGroup> walking_groups() const {
    return core::ConstPointerView<WalkingGroup>(walking_groups_);
  }

  /// Fills `out` with the centres of agents (humans and ARI) closer than `radius_m` to `point`,
  /// except `exclude` and members of group `exclude_group`, in a deterministic order.
  void agent_centres_near(const Eigen::Vector2d& point, double radius_m, const Object* exclude,
                          std::vector<Eigen::Vector2d>& out,
                          model::ObjectId exclude_group = model::kNoObject) const;
  /// How deep (m) an agent's body reaches into walls or furniture; <= 0 when clear.
  double static_penetration_m(const Object& agent) const;
  /// The free-space probe of the reactions to ARI: how far (m) a disc of `radius_m` at `point`
  /// keeps from the nearest wall, piece of furniture or edge of the floor; negative when it
  /// reaches into one. Agents are not obstacles here.
  double static_clearance_m(const Eigen::Vector2d& point, double radius_m) const;

 private:
  // The group script moves its members each step (D6.4 §3.4.1): the one writer from outside.
  friend class GroupNavigation;
  friend class WalkingGroup;
  // Conversations make members speak and look (D6.4's scripts, like the group script).
  friend class GroupConversation;
  friend class ConversationGaze;

  // The objects behind the const lookups, for the requests and the group script to change.
  Object* mutable_object(model::ObjectId id);
  Human* mutable_human(model::ObjectId id);
  /// The speech of a human or ARI; null for any other id.
  SpeechGenerator* mutable_speech(model::ObjectId id);
  /// Steps each group's conversation, dropping those of groups that are gone.
  void step_conversations(const StepContext& context);
  /// Steps each group's turnover (members leaving, passers-by joining), dropping those of groups
  /// that are gone.
  void step_turnovers();
  template <class Part, class StepPart, class DropPart>
  void step_parts_of_groups(std::map<model::ObjectId, std::unique_ptr<Part>>& parts, StepPart step,
                            DropPart drop);
  GroupNavigation* mutable_group(model::ObjectId id);
  WalkingGroup* mutable_walking_group(model::ObjectId id);
  /// The id a new group, walking or conversing, takes: `requested`, or one past the highest id of
  /// any group when it is model::kNoObject (1 for the first group). Refused as `expected` when
  /// another group has it.
  model::ObjectId new_group_id(model::ObjectId requested, const RequestCheck& check,
                               const std::string& expected) const;
  /// Takes a human out of its walking group, if any (a group left without members is dropped).
  void leave_walking_group(Human& human);
  /// Walking groups that arrived with `converse` become conversation groups.
  void converse_on_arrival();
  // The object a request names, or its refusal `<request>: <field>: no human with id 99` (field
  // `id`, `group_id`, or as given).
  Human& existing_human(const RequestCheck& check, model::ObjectId human_id);
  GroupNavigation& existing_group(const RequestCheck& check, model::ObjectId group_id);
  Object& existing_agent(const RequestCheck& check, const std::string& field, model::ObjectId id);
  /// Throws unless every member is a human of the world.
  void check_members(const RequestCheck& check, const std::vector<model::ObjectId>& members) const;
  /// Takes a human out of its group (if any) so a goal, velocity or pose command can drive it.
  void release_from_group(Human& human);
  /// A group has members: one left without any is dropped.
  void drop_empty_groups();
  /// Throws unless the shape at `pose` lies on the floor and overlaps nothing but `ignore`, nor
  /// furniture when `on_a_seat` (a seated human overlaps the chair under them; walls still count).
  void check_placement(const b2Shape& shape, const core::Pose2& pose, const Object* ignore,
                       const std::string& what, bool on_a_seat = false) const;
  void add_floor_fence();
  void register_object(Object& object);
  /// Marks the neighbour grid out of date: call whenever an agent moves, appears or disappears.
  void agents_changed() { agent_grid_stale_ = true; }

  model::WorldDescription world_;
  SimulationConfig config_;
  std::unique_ptr<b2World> physics_;
  std::vector<std::unique_ptr<Object>> statics_;
  std::vector<std::unique_ptr<Human>> humans_;
  std::unique_ptr<Ari> ari_;
  std::vector<std::unique_ptr<GroupNavigation>> groups_;
  std::map<model::ObjectId, std::unique_ptr<GroupConversation>> conversations_;  // by group id
  std::map<model::ObjectId, std::unique_ptr<GroupTurnover>> turnovers_;          // by group id
  std::shared_ptr<const ConversationLines> conversation_lines_;
  std::vector<std::unique_ptr<WalkingGroup>> walking_groups_;
  std::unordered_map<model::ObjectId, Object*> objects_by_id_;
  // Every id an object has had in this simulation, removed objects' included: never reused.
  std::unordered_set<model::ObjectId> used_ids_;
  uint64_t step_count_{0};
  StepDiagnostics diagnostics_;
  // Rebuilt lazily by the first neighbour query after agents changed; a cache, hence mutable.
  mutable AgentGrid agent_grid_;
  mutable bool agent_grid_stale_{true};
};

}  // namespace ari_social_sim::world
