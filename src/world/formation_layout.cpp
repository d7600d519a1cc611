#include "ari_social_sim/world/formation_layout.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "ari_social_sim/core/angles.hpp"

namespace ari_social_sim::world {
namespace {

using model::Arrangement;

// Exhaustive matching is exact and cheap up to this many movable participants (7! orders).
constexpr size_t kMaxExhaustiveParticipants = 7;

Eigen::Vector2d unit(double angle) {
  return {std::cos(angle), std::sin(angle)};
}

// A row of `members` centred at `bearing` from the centre, laid out across the bearing. Members
// of a side-by-side row face the same way, back across their bearing; in a conversation
// (vis-a-vis, L) each turns to the o-space centre, as people at the ends of a row do.
void add_row(const FormationShape& shape, double bearing, size_t members,
             std::vector<FormationSlot>& slots) {
  const Eigen::Vector2d row_centre = shape.centre + shape.radius_m * unit(bearing);
  const Eigen::Vector2d along = unit(bearing + core::kPi / 2);
  for (size_t j = 0; j < members; ++j) {
    const double offset = (static_cast<double>(j) - 0.5 * static_cast<double>(members - 1)) *
                          shape.shoulder_spacing_m;
    const Eigen::Vector2d place = row_centre + offset * along;
    const Eigen::Vector2d to_centre = shape.centre - place;
    const double facing = shape.arrangement == model::Arrangement::kSideBySide
                              ? core::wrap_angle(bearing + core::kPi)
                              : std::atan2(to_centre.y(), to_centre.x());
    slots.push_back({place, facing});
  }
}

double squared_walk(const Eigen::Vector2d& from, const FormationSlot& slot) {
  return (slot.position - from).squaredNorm();
}

}  // namespace

std::vector<FormationSlot> formation_slots(const FormationShape& shape, size_t count) {
  std::vector<FormationSlot> slots;
  slots.reserve(count);
  const double phi = shape.heading_rad;
  const size_t first_row = (count + 1) / 2;
  const size_t second_row = count - first_row;
  switch (shape.arrangement) {
    case Arrangement::kCircle:
      for (size_t k = 0; k < count; ++k) {
        add_row(shape, phi + 2.0 * core::kPi * static_cast<double>(k) / count, 1, slots);
      }
      break;
    case Arrangement::kVisAVis:
    case Arrangement::kLShape: {
      const double second_bearing =
          phi + (shape.arrangement == Arrangement::kVisAVis ? core::kPi : core::kPi / 2);
      add_row(shape, phi, first_row, slots);
      if (second_row > 0) {
        add_row(shape, second_bearing, second_row, slots);
      }
      break;
    }
    case Arrangement::kSideBySide:
      add_row(shape, phi, count, slots);
      break;
  }
  return slots;
}

double row_distance_for(Arrangement arrangement, size_t count, double member_spacing_m,
                        double shoulder_spacing_m) {
  if (arrangement != Arrangement::kLShape) {
    return 0.5 * member_spacing_m;
  }
  // The rows' ends nearest the corner stand a and b off their bearings, so at r from the centre
  // they are sqrt((r - a)^2 + (r - b)^2) apart: at least a shoulder spacing s from
  // r = (a + b + sqrt(2 s^2 - (a - b)^2)) / 2.
  const double s = shoulder_spacing_m;
  // Members on each side of the L, in whole people: the longer side takes the odd one.
  const size_t long_side = (count + 1) / 2;
  const size_t short_side = count / 2;
  const double a = 0.5 * static_cast<double>(long_side - 1) * s;
  const double b = 0.5 * static_cast<double>(short_side > 0 ? short_side - 1 : 0) * s;
  const double corner_clear = 0.5 * (a + b + std::sqrt(2.0 * s * s - (a - b) * (a - b)));
  return std::max(member_spacing_m / std::sqrt(2.0), corner_clear);
}

std::vector<size_t> assign_slots(const std::vector<Eigen::Vector2d>& positions,
                                 const std::vector<FormationSlot>& slots,
                                 const std::vector<size_t>& fixed) {
  const size_t n = positions.size();
  std::vector<size_t> slot_of(n, 0);
  std::vector<bool> slot_taken(slots.size(), false);
  std::vector<bool> placed(n, false);
  auto nearest_free = [&](const Eigen::Vector2d& from) {
    size_t best = slots.size();
    for (size_t s = 0; s < slots.size(); ++s) {
      if (!slot_taken[s] && (best == slots.size() ||
                             squared_walk(from, slots[s]) < squared_walk(from, slots[best]))) {
        best = s;
      }
    }
    return best;
  };
  for (size_t i : fixed) {
    slot_of[i] = nearest_free(positions[i]);
    slot_taken[slot_of[i]] = true;
    placed[i] = true;
  }
  std::vector<size_t> movers, free_slots;
  for (size_t i = 0; i < n; ++i) {
    if (!placed[i]) {
      movers.push_back(i);
    }
  }
  for (size_t s = 0; s < slots.size(); ++s) {
    if (!slot_taken[s]) {
      free_slots.push_back(s);
    }
  }
  if (movers.size() <= kMaxExhaustiveParticipants) {
    // Every order of the free slots, the first of equal cost kept: deterministic.
    std::vector<size_t> order = free_slots;
    std::vector<size_t> best = order;
    double best_cost = std::numeric_limits<double>::infinity();
    do {
      double cost = 0.0;
      for (size_t k = 0; k < movers.size(); ++k) {
        cost += squared_walk(positions[movers[k]], slots[order[k]]);
      }
      if (cost < best_cost) {
        best_cost = cost;
        best = order;
      }
    } while (std::next_permutation(order.begin(), order.end()));
    for (size_t k = 0; k < movers.size(); ++k) {
      slot_of[movers[k]] = best[k];
    }
    return slot_of;
  }
  // Large groups: repeatedly the closest participant and free slot.
  while (!movers.empty()) {
    size_t best_mover = 0;
    size_t best_slot = 0;
    double best_cost = std::numeric_limits<double>::infinity();
    for (size_t k = 0; k < movers.size(); ++k) {
      for (size_t s : free_slots) {
        const double cost = squared_walk(positions[movers[k]], slots[s]);
        if (cost < best_cost) {
          best_cost = cost;
          best_mover = k;
          best_slot = s;
        }
      }
    }
    slot_of[movers[best_mover]] = best_slot;
    movers.erase(movers.begin() + static_cast<std::ptrdiff_t>(best_mover));
    free_slots.erase(std::find(free_slots.begin(), free_slots.end(), best_slot));
  }
  return slot_of;
}

}  // namespace ari_social_sim::world
