#pragma once

#include <Eigen/Core>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "ari_social_sim/core/config_fields.hpp"
#include "ari_social_sim/core/number_text.hpp"
#include "ari_social_sim/core/pose2.hpp"
#include "ari_social_sim/model/fformation_arrangement.hpp"
#include "ari_social_sim/model/object_id.hpp"
#include "ari_social_sim/world/conversation_spec.hpp"
#include "ari_social_sim/world/formation_layout.hpp"
#include "ari_social_sim/world/group_turnover_spec.hpp"
#include "ari_social_sim/world/member_manner.hpp"
#include "ari_social_sim/world/object.hpp"

namespace ari_social_sim::world {

class Human;

/// Most members one group may have: an F-formation of more people is a crowd.
constexpr size_t kMaxGroupMembers = 50;
/// Largest o-space radius and member spacing (m) a group may be given.
constexpr double kMaxOspaceRadiusM = 10.0;
/// Largest place_gain (m/s per m): a stiffer pull would overshoot within one 0.05 s step.
constexpr double kMaxPlaceGain = 10.0;
/// Largest facing_spread (deg): beyond it members would no longer face their o-space.
constexpr double kMaxFacingSpreadDeg = 45.0;
/// spacing_factor stays below this, under the golden ratio: in a group of five, neighbours two
/// places apart stand 1.618 chords apart and must not repel each other.
constexpr double kMaxSpacingFactor = 1.6;
/// Largest spacing_spread: beyond it one member in twenty would stand over 7 times as far out as
/// another.
constexpr double kMaxSpacingSpread = 1.0;
/// Largest shift (m): standing members shift their weight, they do not walk about.
constexpr double kMaxShiftM = 0.3;
/// Largest shift_interval (s).
constexpr double kMaxShiftIntervalS = 600.0;

/// A conversational group's parameters (D6.4 §3.4.1).
struct GroupSpec {
  model::ObjectId id{model::kNoObject};
  std::vector<model::ObjectId> members;
  /// o: goal position of the o-space centre (m, map frame).
  Eigen::Vector2d centre{Eigen::Vector2d::Zero()};
  /// s (m); 0 = derived from the member count so that members stand `member_spacing_m` apart
  /// (see ospace_radius_for), at least `min_ospace_radius_m`.
  double ospace_radius_m{0.0};
  double min_ospace_radius_m{0.45};
  /// m between neighbours across an automatic o-space; 0 = by the participant count
  /// (GroupNavigation::default_member_spacing_m): real groups stand wider the more they are.
  double member_spacing_m{0.0};
  /// Delta_s (m): radius of a member's social space for the equality force (eq. 3.13-3.16).
  double social_distance_m{3.0};
  /// Members repel each other within spacing_factor x the chord between evenly spaced neighbours
  /// (the group's personal distance Delta_p), so repulsion spreads them evenly around the o-space
  /// with a spring that does not vanish at the even spacing. The outward push at even spacing is
  /// (Delta_p - chord)^2 whichever members are in range, and cohesion_radius_m() balances it.
  double spacing_factor{1.5};
  /// eta / step (m/s per unit force): the group's own step length (D6.4 §3.4.1 lists it among the
  /// script's properties). Faster than walking alone, so members settle within ~30 s; each step is
  /// still capped at the member's max_speed.
  double step_speed_mps{2.0};
  /// Kendon's arrangement the members keep (docs/world.md "Arrangements"). A circle is kept by
  /// D6.4's forces; the others by a place for each member in rows around the o-space.
  model::Arrangement arrangement{model::Arrangement::kCircle};
  /// Bearing (rad, map frame) of the first row from the o-space centre; unset = from where the
  /// members stand when the group forms.
  std::optional<double> heading_rad;
  /// m between neighbours standing shoulder to shoulder in one row (side-by-side, and the rows
  /// of larger vis-a-vis and L groups): the median of the recorded side-by-side pairs (0.61 m,
  /// 10th-90th percentile 0.40-1.19, docs/perception_gcff.md).
  double shoulder_spacing_m{0.6};
  /// deg: standard deviation of each member's stance, the turn of their body off the way the
  /// formation has them face (seeded per member). People do not face an o-space exactly: recorded
  /// members of pairs turn 0-23 deg off it, of triads 1-94 deg (10th-90th percentile,
  /// docs/perception_gcff.md). The stance alone left the world's medians at 6-9 deg; attention
  /// and the passing turns add to it (docs/world.md section 4.5).
  double facing_spread_deg{15.0};
  /// Standard deviation of the natural log of the group's spacing scale, and of each member's
  /// (seeded per group and per member, cut at 2 sd): factors on the o-space radius and row
  /// spacing, and on each member's distance to the centre, in groups of up to
  /// kSpacingSpreadUpTo participants. Recorded pairs stand from about 0.65 m to 1.5 m apart
  /// (docs/world.md), not all at one spacing.
  double spacing_spread{0.2};
  /// spacing_spread for a side-by-side row's factor on its shoulder spacing (the same draw);
  /// unset = spacing_spread. Recorded pairs side by side stand 0.40-1.19 m apart, spread wider
  /// than other pairs; 0.6 matches them, at a cost to GCFF (docs/world.md section 4.5).
  std::optional<double> row_spacing_spread;
  /// deg: facing_spread for the members of a side-by-side row; unset = facing_spread. Recorded
  /// pairs side by side turn 12-62 deg off their o-space; 35 matches them.
  std::optional<double> row_facing_spread_deg;
  /// Share (0-1) of the turn toward whom a member attends to, in groups of three or more: people
  /// orient to the one they talk with, not to the o-space alone. The one attended to changes at
  /// each shift.
  double attention{0.3};
  /// m: standard deviation of each coordinate of a member's passing shift off its place, drawn
  /// anew at each shift (cut at 2 sd): talking people shift their weight and step a little.
  double shift_m{0.03};
  /// deg: standard deviation of a member's passing turn, drawn anew at each shift (cut at 2 sd).
  double shift_turn_deg{10.0};
  /// s: mean time between a member's shifts (exponential, seeded per member).
  double shift_interval_s{4.0};
  /// m/s per m: how strongly each member of a circle is pulled to its evenly spaced place (0:
  /// D6.4's forces alone, under which a newcomer can settle inside the ring and the others
  /// bunch). Rows always hold their members to their places.
  double place_gain{1.0};
  /// How the members talk among themselves, and with ARI when it joins (group_conversation.hpp).
  ConversationSpec conversation;
  /// Members who leave and passers-by who join on their own (group_turnover.hpp); off by default.
  GroupTurnoverSpec turnover;

  /// A group as a scene file's `groups` entry writes it (config_fields.hpp).
  template <class V>
  void visit(V& v) {
    v.field(core::required("id"), id, "the group's id, unique among groups", core::positive());
    v.field(core::required("members"), members, "ids of the humans in the group", core::positive());
    v.rule("members", !members.empty(), "at least one human", "none");
    v.rule("members", members.size() <= kMaxGroupMembers,
           "at most " + std::to_string(kMaxGroupMembers) + " humans",
           std::to_string(members.size()));
    v.rule("members", !lists_a_member_twice(), "each human once", "a human listed twice");
    v.field(core::required("centre"), centre, "m, o: where the o-space centre goes (map frame)");
    v.field("ospace_radius", ospace_radius_m,
            "m, s: radius of the o-space; 0 = from the member count, members member_spacing "
            "apart",
            core::between(0.0, kMaxOspaceRadiusM));
    v.field("min_ospace_radius", min_ospace_radius_m, "m, least radius of an automatic o-space",
            {0.0, kMaxOspaceRadiusM, true});
    v.field("member_spacing", member_spacing_m,
            "m between neighbouring members of an automatic o-space; 0 = by the participant "
            "count (0.9 m for two, 1.0 for three, 1.1 for four, 0.9 from five on)",
            core::between(0.0, kMaxOspaceRadiusM));
    v.field("social_distance", social_distance_m,
            "m (Delta_s): radius of a member's social space for the equality force",
            core::positive());
    v.field("spacing_factor", spacing_factor,
            "members repel within spacing_factor x the chord between evenly spaced neighbours",
            core::between(1.0, kMaxSpacingFactor));
    v.rule("spacing_factor", spacing_factor < kMaxSpacingFactor,
           "a number below " + core::number_text(kMaxSpacingFactor),
           core::number_text(spacing_factor));
    v.field("step_speed", step_speed_mps, "m/s per unit force: the group's step length eta / step",
            core::positive());
    v.choice("arrangement", arrangement, "F-formation the members keep", model::kArrangements);
    v.field("heading", heading_rad,
            "rad, bearing of the first row from the o-space centre; unset = from where the "
            "members stand",
            core::between(-core::kMaxHeadingRad, core::kMaxHeadingRad));
    v.field("facing_spread", facing_spread_deg,
            "deg, standard deviation of each member's body turn off the formation's facing",
            core::between(0.0, kMaxFacingSpreadDeg));
    v.field("spacing_spread", spacing_spread,
            "standard deviation of the log of the group's factor on its spacing and of each "
            "member's on its distance to the centre (groups of up to three)",
            core::between(0.0, kMaxSpacingSpread));
    v.field("row_facing_spread", row_facing_spread_deg,
            "deg, facing_spread for the members of a side-by-side row; unset = facing_spread",
            core::between(0.0, kMaxFacingSpreadDeg));
    v.field("row_spacing_spread", row_spacing_spread,
            "spacing_spread for a side-by-side row's factor on its shoulder spacing; unset = "
            "spacing_spread",
            core::between(0.0, kMaxSpacingSpread));
    v.field("attention", attention,
            "share of the turn toward whom a member attends to (groups of three or more)",
            core::between(0.0, 1.0));
    v.field("shift", shift_m,
            "m, standard deviation of each coordinate of a member's passing shift off its place",
            core::between(0.0, kMaxShiftM));
    v.field("shift_turn", shift_turn_deg,
            "deg, standard deviation of a member's passing turn off its facing",
            core::between(0.0, kMaxFacingSpreadDeg));
    v.field("shift_interval", shift_interval_s, "s, mean time between a member's shifts",
            {0.0, kMaxShiftIntervalS, true});
    v.field("place_gain", place_gain,
            "m/s per m: pull of each member of a circle to its evenly spaced place; 0 = D6.4's "
            "forces alone",
            core::between(0.0, kMaxPlaceGain));
    v.section("conversation", conversation,
              "how the members talk among themselves and with ARI (docs/world.md, section 12)");
    v.section("turnover", turnover,
              "members who leave and passers-by who join on their own (docs/world.md, section "
              "4.7)");
    v.field("shoulder_spacing", shoulder_spacing_m,
            "m between neighbours side by side in one row (side-by-side, larger vis-a-vis and "
            "L groups)",
            {0.0, kMaxOspaceRadiusM, true});
  }

  /// True when a human appears twice in `members`.
  bool lists_a_member_twice() const;

  /// Throws core::RequestError naming the first field outside what visit allows, its value and
  /// the expectation (id 0, no members or more than kMaxGroupMembers, a member twice, a radius or
  /// spacing outside its range, ...). Whether the centre lies on the floor is the simulation's
  /// check (Simulation::add_group).
  void validate() const;
};

/// How near (m) beyond its o-space radius ARI must come, facing the o-space centre, for a group to
/// open a place for it, and how far beyond it ARI must go again for the group to close it. Near:
/// members who start shifting while ARI is still far move the place ARI aims at, and, with
/// perception's detectors, turn from its cameras long enough for ARI to lose them (at 1.5 m one
/// live run in two of scenario_perception_modes.test perception:=detectors failed to join).
constexpr double kRobotJoinReachM = 0.8;
constexpr double kRobotLeaveReachM = 2.5;
/// Within this distance (m) of a circle's ring, ARI's place stops following it round.
constexpr double kRobotSettledM = 0.6;
/// ARI faces the o-space centre when its heading is within this angle (rad, 45 deg) of it.
constexpr double kRobotJoinFacingRad = 0.7853981633974483;

/// In rows, members repel one another within this share of the closest two places' distance.
constexpr double kRowSpacingShare = 0.85;
/// The group's and its members' own spacings apply while the group has at most this many
/// participants (the sizes recorded, docs/world.md section 4.5): wider or uneven circles of four
/// and more are split by perception's GCFF (a human joining a group of three was counted in 90
/// of 100 episodes with them, 100 without).
constexpr size_t kSpacingSpreadUpTo = 3;

/// Members' own places (their formation places moved by their spacing and shifts) stay at least
/// this far (m) apart: two bodies' width (0.4 m) and room between the shoulders.
constexpr double kLeastMemberGapM = 0.55;

/// A member farther than this (m) from its place in a row faces where it walks.
constexpr double kFacePlaceWithinM = 0.5;

/// D6.4 §3.4.1 GroupNavigation script: moves its members into an F-formation around the o-space
/// centre and keeps it. A circle is kept with D6.4's repulsion, equality and cohesion forces
/// (eq. 3.9-3.18); vis-a-vis, l-shape and side-by-side give each member a place in rows
/// (formation_layout.hpp) that a cohesion force toward the place holds, with the same
/// repulsion. The formation counts its participants: the members, and ARI while it joins
/// (when it comes within kRobotJoinReachM of the p-space facing the centre, or when asked to
/// join), so that the members open a place for it and close it when it leaves. The simulation
/// steps each group after the sensors (D6.4's scripts).
class GroupNavigation {
 public:
  explicit GroupNavigation(const GroupSpec& spec);

  void step(const StepContext& context);

  model::ObjectId id() const { return spec_.id; }
  const GroupSpec& spec() const { return spec_; }
  const std::vector<model::ObjectId>& members() const { return spec_.members; }
  const Eigen::Vector2d& centre() const { return spec_.centre; }
  /// The arrangement kept now: the configured one, except that rows (vis-a-vis, l-shape,
  /// side-by-side) joined by more participants than they were formed with become a circle
  /// (D6.4 §3.4.2: a third person turns an L into a circle), and a circle of two stands
  /// vis-a-vis.
  model::Arrangement arrangement() const;
  /// Bearing (rad) of the first row from the centre; unset until the group first steps when the
  /// spec left it to the members' places.
  const std::optional<double>& heading_rad() const { return heading_rad_; }
  /// ARI while it takes part in the formation (joining or joined), else kNoObject.
  model::ObjectId robot_joining() const { return robot_joining_; }
  /// Each participant's place (members in order, then ARI while it joins) as of the last step;
  /// empty for a circle with place_gain 0.
  const std::vector<FormationSlot>& places() const { return places_; }
  /// Members, plus ARI while it joins.
  size_t participant_count() const;
  /// s (m) in use: the configured radius, or the one derived from the participant count times the
  /// group's seeded spacing scale (drawn at its first step).
  double ospace_radius_m() const;
  /// Delta_p (m) between members: spacing_factor x chord of evenly spaced members on the circle.
  double member_personal_distance_m() const;
  /// Radius (m) the cohesion force (eq. 3.17) pulls toward: s less the outward push of the
  /// members' mutual repulsion at even spacing, so that the formation settles on s itself.
  double cohesion_radius_m() const;

  void add_member(model::ObjectId id);
  void remove_member(model::ObjectId id);
  /// Expects a finite centre: requests are checked by Simulation::set_group_centre.
  void set_centre(const Eigen::Vector2d& centre);
  /// A new arrangement for the present members; an unset heading is taken again from where
  /// they stand. Expects a finite heading: requests are checked by Simulation.
  void set_arrangement(model::Arrangement arrangement, std::optional<double> heading_rad);
  /// ARI asked to join (kept until robot_leave) or to leave (and not counted again until it has
  /// gone kRobotLeaveReachM away).
  void robot_join(model::ObjectId ari_id);
  void robot_leave();

  /// m between neighbours across an automatic o-space of `participants` when member_spacing is
  /// 0: 0.9 for two, 1.0 for three, 1.1 for four, as real groups stand wider the more they are;
  /// 0.9 again from five on, where wider circles are split by perception's GCFF (docs/world.md
  /// section 4.3).
  static double default_member_spacing_m(size_t participants);
  /// The spec's member_spacing, or default_member_spacing_m when it is 0.
  static double member_spacing_for(const GroupSpec& spec, size_t participants);

  /// Each member's manner (stance, spacing, shifts), by member id, once the group has stepped.
  const MemberManner* manner_of(model::ObjectId member) const;

  /// Radius (m) at which `member_count` evenly spaced members stand `spacing_m` apart:
  /// spacing = 2 s sin(pi / n), never below `min_radius_m`.
  static double ospace_radius_for(size_t member_count, double spacing_m, double min_radius_m);

  /// Radius (m) of the circle, or distance of the rows from the centre, that `participants` keep
  /// in `arrangement`: the spec's ospace_radius when set, else ospace_radius_for a circle and
  /// row_distance_for rows.
  static double formation_radius_for(const GroupSpec& spec, model::Arrangement arrangement,
                                     size_t participants);

  /// Where `participants` stand once settled in the spec's arrangement around its centre, rows
  /// laid out from its heading (0 when unset): scene builders spawn members at these places.
  static FormationShape settled_shape(const GroupSpec& spec, size_t participants);

 private:
  // Whether ARI takes part this step: asked to, or near and facing the centre (hysteresis
  // between kRobotJoinReachM and kRobotLeaveReachM).
  void update_robot_joining(const Simulation& simulation);
  void resolve_heading();
  // True while D6.4's forces keep a circle: configured so, or rows outgrown by joining.
  bool kept_as_circle() const;
  // Deals the participants their places (after a change of participants or arrangement) and
  // moves the places with the centre; a circle without place_gain has none.
  void deal_places(bool circle);
  // While a member is still more than kFacePlaceWithinM from its place, participants trade places
  // when that shortens their walks (paths that cross jam).
  void trade_places_while_forming();
  void step_circle(const StepContext& context);
  void step_rows(const StepContext& context);
  // Fills others_ with every participant but the i-th, outsiders_ with the agents near `p`
  // outside the formation.
  void others_than(size_t i);
  void outsiders_of(const Simulation& simulation, const Human& human, const Eigen::Vector2d& p);
  void move_member(Human& human, const Eigen::Vector2d& force, double turn_rad, double dt_s) const;
  MannerParams manner_params() const;
  // The group's spacing scale while it has at most kSpacingSpreadUpTo participants, else 1.
  double spacing_scale_in_use() const;
  // Whether the group stands as a side-by-side row now (not kept as a circle).
  bool stands_in_a_row() const;
  // The factor on the rows' shoulder spacing: the row's own for a side-by-side row, else the
  // group's spacing scale; 1 beyond kSpacingSpreadUpTo participants.
  double shoulder_scale_in_use() const;
  // Draws the group's spacing scale at its first step (the seed is the simulation's).
  void draw_group_spacing(uint64_t seed);
  // Draws each member's manner when first met and its next shift when due.
  void update_manners(const StepContext& context);
  // How much farther (m) from the centre than its formation place, at from_centre_m, the i-th
  // member stands by its spacing scale.
  double own_spacing_offset_m(size_t i, double from_centre_m) const;
  // Each member's own place this step (own_places_): its formation place moved by its spacing
  // and shift, kept kLeastMemberGapM from the others.
  void place_members_apart();
  // The way (rad) the i-th member at p faces, given the formation's facing there: turned by its
  // stance and shift, and by `attention` toward whom it attends to.
  double own_facing(size_t i, const Eigen::Vector2d& p, double formation_facing_rad) const;
  // The participants changed: places are dealt again.
  void formation_changed() { slots_stale_ = true; }

  GroupSpec spec_;
  // The member count the arrangement was set for (a dyad's arrangement grows into a circle).
  size_t arranged_size_{0};
  std::optional<double> heading_rad_;
  double circle_heading_rad_{0.0};
  model::ObjectId robot_joining_{model::kNoObject};
  bool robot_asked_to_join_{false};
  bool robot_asked_to_leave_{false};
  bool slots_stale_{true};
  bool was_circle_{true};
  std::vector<size_t> slot_of_;  // per participant (members, then ARI)
  std::vector<FormationSlot> places_;
  std::optional<double> group_spacing_scale_;
  std::optional<double> row_spacing_scale_;  // side-by-side rows' factor on the shoulder spacing
  std::map<model::ObjectId, MemberManner> manners_;
  std::vector<Eigen::Vector2d> own_places_;          // per member, this step; empty without places
  std::vector<const MemberManner*> member_manners_;  // per member, this step
  std::vector<model::ObjectId> participant_ids_;     // members, then ARI while it joins
  std::vector<Eigen::Vector2d> participant_positions_;  // scratch
  std::vector<Eigen::Vector2d> social_neighbours_;
  std::vector<Eigen::Vector2d> others_;
  std::vector<Eigen::Vector2d> outsiders_;
};

}  // namespace ari_social_sim::world
