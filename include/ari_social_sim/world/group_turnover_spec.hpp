#pragma once

#include <string>

#include "ari_social_sim/core/config_fields.hpp"

namespace ari_social_sim::world {

/// Most people a group takes in on its own (GroupTurnoverSpec::max_members); a scene's groups may
/// list more (kMaxGroupMembers).
constexpr int kMaxTurnoverMembers = 6;
/// Highest departure or arrival rate (per minute) a group may name: one a second is a crowd
/// milling, not a conversation.
constexpr double kMaxTurnoverRatePerMin = 60.0;

/// Members who leave a conversation group and passers-by who join it on their own over a run
/// (docs/world.md section 4.7). Off by default: a scene's groups keep who they have unless the
/// scene asks for turnover, so a script's people stay where it put them.
struct GroupTurnoverSpec {
  /// Departures per member per minute: each member leaves at this rate, one at a time.
  double leave_rate_per_min{0.0};
  /// Arrivals per minute: at this rate the nearest passer-by within join_radius joins.
  double join_rate_per_min{0.0};
  /// m from the o-space centre within which a person in no group may join.
  double join_radius_m{4.0};
  /// m from the o-space centre a leaving member walks to (where the floor is free).
  double leave_distance_m{4.0};
  /// Nobody leaves a group this small.
  int min_members{2};
  /// No passer-by joins a group this large.
  int max_members{5};

  bool active() const { return leave_rate_per_min > 0.0 || join_rate_per_min > 0.0; }

  template <class V>
  void visit(V& v) {
    const core::Bounds rate = core::between(0.0, kMaxTurnoverRatePerMin);
    v.field("leave_rate", leave_rate_per_min,
            "departures per member per minute (0: nobody leaves on their own)", rate);
    v.field("join_rate", join_rate_per_min,
            "arrivals per minute of passers-by within join_radius (0: nobody joins on their own)",
            rate);
    v.field("join_radius", join_radius_m,
            "m from the o-space centre within which a person in no group may join",
            core::between(0.5, 20.0));
    v.field("leave_distance", leave_distance_m,
            "m from the o-space centre a leaving member walks to", core::between(1.0, 20.0));
    v.field("min_members", min_members, "members below which nobody leaves",
            core::between(1, kMaxTurnoverMembers));
    v.field("max_members", max_members, "members at which nobody more joins",
            core::between(2, kMaxTurnoverMembers));
    v.rule("max_members", min_members < max_members, "an integer above min_members",
           std::to_string(max_members));
  }
};

}  // namespace ari_social_sim::world
