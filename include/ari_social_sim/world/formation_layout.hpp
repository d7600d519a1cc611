#pragma once

#include <Eigen/Core>
#include <vector>

#include "ari_social_sim/model/fformation_arrangement.hpp"

// Where the members of an F-formation stand in each of Kendon's arrangements (D6.4 §3.4,
// docs/world.md "Arrangements"). The circle is kept by D6.4's forces alone; the other
// arrangements give every participant a place (a slot) that the group script pulls them to.

namespace ari_social_sim::world {

/// One participant's place in a formation and the way they face there (rad, map frame).
struct FormationSlot {
  Eigen::Vector2d position{Eigen::Vector2d::Zero()};
  double facing_rad{0.0};
};

/// An arrangement placed in the map.
struct FormationShape {
  model::Arrangement arrangement{model::Arrangement::kCircle};
  Eigen::Vector2d centre{Eigen::Vector2d::Zero()};
  /// Bearing (rad) from the o-space centre of the first row (of the first slot in a circle).
  double heading_rad{0.0};
  /// Distance (m) of the rows, or of the circle, from the o-space centre.
  double radius_m{0.55};
  /// Distance (m) between neighbours standing shoulder to shoulder in one row.
  double shoulder_spacing_m{0.6};
};

/// The places of `count` participants. A circle spreads them evenly at radius_m, facing the
/// centre. The others stand in rows centred on their bearing, facing the o-space across it:
/// vis-a-vis in two rows on opposite sides (the first has the odd participant), l-shape in two
/// rows at a right angle (the first has the odd participant), side-by-side in one row. Slots are
/// ordered row by row.
std::vector<FormationSlot> formation_slots(const FormationShape& shape, size_t count);

/// The arrangement's automatic row distance (m) for `count` participants, `member_spacing_m`
/// apart across the o-space and `shoulder_spacing_m` along a row: half of member_spacing_m face
/// to face and in a side-by-side row's o-space; at a right angle 1/sqrt(2) of it (so the two of an
/// L stand member_spacing_m apart), or further when the rows' nearest ends would stand closer
/// than shoulder_spacing_m. Circles use GroupNavigation::ospace_radius_for.
double row_distance_for(model::Arrangement arrangement, size_t count, double member_spacing_m,
                        double shoulder_spacing_m);

/// The slot each participant takes: slot_of[i] for participant i, a permutation of the slots
/// that keeps the sum of squared walks smallest (exhaustively for up to 7 participants, then
/// greedily, nearest pair first). Participants listed in `fixed` (indices) are placed first, in
/// their nearest free slot: agents the script does not move, such as ARI joining.
std::vector<size_t> assign_slots(const std::vector<Eigen::Vector2d>& positions,
                                 const std::vector<FormationSlot>& slots,
                                 const std::vector<size_t>& fixed);

}  // namespace ari_social_sim::world
