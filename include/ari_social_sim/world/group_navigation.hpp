#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "ari_social_sim/core/config_fields.hpp"
#include "ari_social_sim/core/number_text.hpp"
#include "ari_social_sim/model/object_id.hpp"
#include "ari_social_sim/world/object.hpp"

namespace ari_social_sim::world {

class Human;

/// Most members one group may have: an F-formation of more people is a crowd.
constexpr size_t kMaxGroupMembers = 50;
/// Largest o-space radius and member spacing (m) a group may be given.
constexpr double kMaxOspaceRadiusM = 10.0;
/// spacing_factor stays below this, under the golden ratio: in a group of five, neighbours two
/// places apart stand 1.618 chords apart and must not repel each other.
constexpr double kMaxSpacingFactor = 1.6;

/// A conversational group's parameters (D6.4 §3.4.1).
struct GroupSpec {
  model::ObjectId id{model::kNoObject};
  std::vector<model::ObjectId> members;
  /// o: goal position of the o-space centre (m, map frame).
  Eigen::Vector2d centre{Eigen::Vector2d::Zero()};
  /// s (m); 0 = derived from the member count so that members stand `member_spacing_m` apart
  /// (see ospace_radius_for), at least `min_ospace_radius_m`.
  double ospace_radius_m{0.0};
  double min_ospace_radius_m{0.6};
  double member_spacing_m{1.1};
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
            "m between neighbouring members of an automatic o-space",
            {0.0, kMaxOspaceRadiusM, true});
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
  }

  /// True when a human appears twice in `members`.
  bool lists_a_member_twice() const;

  /// Throws core::RequestError naming the first field outside what visit allows, its value and
  /// the expectation (id 0, no members or more than kMaxGroupMembers, a member twice, a radius or
  /// spacing outside its range, ...). Whether the centre lies on the floor is the simulation's
  /// check (Simulation::add_group).
  void validate() const;
};

/// D6.4 §3.4.1 GroupNavigation script: moves its members with repulsion, equality and cohesion
/// forces (eq. 3.9-3.18) into a circular F-formation around the o-space centre. The simulation
/// steps each group after the sensors (D6.4's scripts).
class GroupNavigation {
 public:
  explicit GroupNavigation(const GroupSpec& spec);

  void step(const StepContext& context);

  model::ObjectId id() const { return spec_.id; }
  const std::vector<model::ObjectId>& members() const { return spec_.members; }
  const Eigen::Vector2d& centre() const { return spec_.centre; }
  /// s (m) in use: the configured radius or the one derived from the member count.
  double ospace_radius_m() const;
  /// Delta_p (m) between members: spacing_factor x chord of evenly spaced members on the circle.
  double member_personal_distance_m() const;
  /// Radius (m) the cohesion force (eq. 3.17) pulls toward: s less the outward push of the
  /// members' mutual repulsion at even spacing, so that the formation settles on s itself.
  double cohesion_radius_m() const;

  void add_member(model::ObjectId id) { spec_.members.push_back(id); }
  void remove_member(model::ObjectId id);
  /// Expects a finite centre: requests are checked by Simulation::set_group_centre.
  void set_centre(const Eigen::Vector2d& centre);

  /// Radius (m) at which `member_count` evenly spaced members stand `spacing_m` apart:
  /// spacing = 2 s sin(pi / n), never below `min_radius_m`.
  static double ospace_radius_for(size_t member_count, double spacing_m, double min_radius_m);

 private:
  GroupSpec spec_;
  std::vector<Eigen::Vector2d> member_positions_;  // scratch
  std::vector<Eigen::Vector2d> social_neighbours_;
  std::vector<Eigen::Vector2d> others_;
  std::vector<Eigen::Vector2d> outsiders_;
};

}  // namespace ari_social_sim::world
