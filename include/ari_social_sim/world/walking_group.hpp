#pragma once

#include <Eigen/Core>
#include <vector>

#include "ari_social_sim/core/config_fields.hpp"
#include "ari_social_sim/core/pose2.hpp"
#include "ari_social_sim/model/fformation_arrangement.hpp"
#include "ari_social_sim/model/object_id.hpp"
#include "ari_social_sim/world/group_navigation.hpp"
#include "ari_social_sim/world/object.hpp"
#include "ari_social_sim/world/walking_route.hpp"

namespace ari_social_sim::world {

/// How a walking group's members walk (Moussaïd et al. 2010, docs/world.md "Walking groups"):
/// abreast, or one behind the other.
enum class WalkingFormation : uint8_t { kSideBySide = 0, kLine = 1 };

inline constexpr core::Choice<WalkingFormation> kWalkingFormations[] = {
    {WalkingFormation::kSideBySide, "side-by-side"}, {WalkingFormation::kLine, "line"}};

inline const char* to_string(WalkingFormation formation) {
  return core::choice_name(formation, kWalkingFormations);
}

/// What a walking group does at its goal: stand there in its formation, or form a conversation
/// group (GroupNavigation) around the goal.
enum class ArrivalAction : uint8_t { kStop = 0, kConverse = 1 };

inline constexpr core::Choice<ArrivalAction> kArrivalActions[] = {
    {ArrivalAction::kStop, "stop"}, {ArrivalAction::kConverse, "converse"}};

inline const char* to_string(ArrivalAction action) {
  return core::choice_name(action, kArrivalActions);
}

/// Fewest and most members of a walking group: larger groups split up in the street.
constexpr size_t kMinWalkingGroupMembers = 2;
constexpr size_t kMaxWalkingGroupMembers = 4;
/// Clearance (m) members keep from walls and furniture beyond their body radius: the route keeps
/// it, and an abreast row needs it at its ends.
constexpr double kWalkingWallMarginM = 0.1;

/// A walking group's parameters (docs/world.md "Walking groups").
struct WalkingGroupSpec {
  /// Shares the id space of conversation groups: on arrival with `converse` the conversation group
  /// takes this id.
  model::ObjectId id{model::kNoObject};
  std::vector<model::ObjectId> members;
  WalkingFormation formation{WalkingFormation::kSideBySide};
  /// Where the group goes (map frame); members face `goal.theta` when they stop there.
  core::Pose2 goal;
  /// m/s of the group. Moussaïd et al. (2010) found the mean speed falling with group size n, by
  /// fits of 1.26 - 0.04 n m/s at low density and 1.24 - 0.08 n at moderate density (1.08 m/s
  /// for pairs, 1.00 for triads): slower than people walking alone.
  double speed_mps{1.05};
  /// m between the centres of neighbours walking abreast: shoulder to shoulder with a little room.
  double spacing_m{0.75};
  /// m between the centres of consecutive walkers in a line: a step and a half behind.
  double line_spacing_m{1.0};
  /// m a member may fall behind its place before the group slows; at twice it the group stands
  /// and waits.
  double wait_distance_m{0.75};
  ArrivalAction on_arrival{ArrivalAction::kStop};
  /// The F-formation formed around the goal on arrival with `converse`.
  model::Arrangement arrangement{model::Arrangement::kCircle};

  /// A walking group as a scene file's `walking_groups` entry writes it (config_fields.hpp).
  template <class V>
  void visit(V& v) {
    v.field(core::required("id"), id, "the walking group's id, unique among all groups",
            core::positive());
    v.field(core::required("members"), members, "ids of the humans walking together",
            core::positive());
    v.rule("members",
           members.size() >= kMinWalkingGroupMembers && members.size() <= kMaxWalkingGroupMembers,
           std::to_string(kMinWalkingGroupMembers) + " to " +
               std::to_string(kMaxWalkingGroupMembers) + " humans",
           std::to_string(members.size()));
    v.rule("members", !lists_a_member_twice(), "each human once", "a human listed twice");
    v.choice("formation", formation, "abreast (side-by-side) or one behind the other (line)",
             kWalkingFormations);
    v.section(core::required("goal"), goal, "where the group walks to (map frame)");
    v.field("speed", speed_mps, "m/s, walking speed of the group", core::Bounds{0.0, 2.0, true});
    v.field("spacing", spacing_m, "m between neighbours walking abreast", core::between(0.4, 2.0));
    v.field("line_spacing", line_spacing_m, "m between consecutive walkers in a line",
            core::between(0.5, 3.0));
    v.field("wait_distance", wait_distance_m,
            "m a member may fall behind its place before the group slows (it stops at twice it)",
            core::between(0.1, 5.0));
    v.choice("on_arrival", on_arrival, "stand at the goal, or form a conversation group there",
             kArrivalActions);
    v.choice("arrangement", arrangement, "F-formation formed on arrival with converse",
             model::kArrangements);
  }

  bool lists_a_member_twice() const;

  /// Throws core::RequestError naming the first field outside what visit allows. Whether the goal
  /// lies on the floor and can be walked to is the simulation's check
  /// (Simulation::add_walking_group).
  void validate() const;
};

/// A walking group script: two to four people walking together to a goal (docs/world.md
/// "Walking groups"). A virtual leader follows a WalkingRoute around walls and furniture at the
/// group's speed; each member has a place relative to the leader and the walking direction
/// (abreast: a row across the route centred on the leader; line: one behind the other along the
/// route, the first at the leader) and walks with the leader's velocity plus a pull toward its
/// place, with the repulsion of D6.4 eq. 3.6 from the other members and from outsiders. Where the
/// route is too narrow for the row (a door, a corridor, furniture), an abreast group falls into a
/// line, and re-forms once its last member is through. The leader slows while a member lags
/// behind its place and waits for it. At the goal the members stand, facing the goal's heading,
/// or the simulation turns them into a conversation group. The simulation steps it after the
/// sensors, like GroupNavigation.
class WalkingGroup {
 public:
  /// `route` goes from the members' centroid to the goal; `body_radius_m` is the widest member's.
  WalkingGroup(const WalkingGroupSpec& spec, WalkingRoute route, double body_radius_m,
               const std::vector<Eigen::Vector2d>& member_positions);

  void step(const StepContext& context);

  model::ObjectId id() const { return spec_.id; }
  const WalkingGroupSpec& spec() const { return spec_; }
  const std::vector<model::ObjectId>& members() const { return spec_.members; }
  const WalkingRoute& route() const { return route_; }
  /// The formation walked now: a side-by-side group walks in a line where the way narrows.
  WalkingFormation formation() const { return formation_; }
  /// The virtual leader's place on the route (map frame) and the walking direction there (rad).
  Eigen::Vector2d leader() const { return route_.point_at(progress_m_); }
  double heading_rad() const;
  double progress_m() const { return progress_m_; }
  /// True while the leader stands because a member fell behind.
  bool is_waiting() const { return waiting_; }
  /// True once the leader is at the goal and every member at its place.
  bool has_arrived() const { return arrived_; }
  /// Half the width (m) of the route an abreast row of `count` needs: the row's half length, a
  /// body radius and the wall margin.
  double abreast_half_width_m(size_t count) const;
  /// The conversation group formed on arrival with `converse`: this id, the members, the o-space
  /// centre on the goal, the spec's arrangement.
  GroupSpec conversation() const;

  void remove_member(model::ObjectId id);

  /// The members' places in `formation` for the leader `s_m` along the route, each facing the
  /// walking direction there (ordered as members()).
  std::vector<FormationSlot> places(WalkingFormation formation, double s_m) const;

 private:
  // Which formation the route allows around the leader, and the slot order for it.
  WalkingFormation formation_for_route() const;
  void order_members(WalkingFormation formation, const std::vector<Eigen::Vector2d>& positions);

  WalkingGroupSpec spec_;
  WalkingRoute route_;
  double body_radius_m_;
  WalkingFormation formation_;
  double progress_m_{0.0};
  bool waiting_{false};
  bool arrived_{false};
  // slot_of_[i]: member i's place in the row (0 = leftmost) or the line (0 = first).
  std::vector<size_t> slot_of_;
  std::vector<Eigen::Vector2d> positions_;  // scratch
  std::vector<Eigen::Vector2d> others_;
  std::vector<Eigen::Vector2d> outsiders_;
};

}  // namespace ari_social_sim::world
