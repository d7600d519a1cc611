#pragma once

#include <string>
#include <vector>

#include "ari_social_sim/model/tracked_person.hpp"
#include "ari_social_sim/navigation/scene_tracker.hpp"

namespace ari_social_sim::navigation {

/// A group perception reports (/humans/interactions/groups): its id and its members' person ids.
struct ReportedGroup {
  std::string group_id;
  double stamp_s{0.0};
  std::vector<std::string> members;
};

/// What social navigation takes from perception in one cycle: the persons tracked now with their
/// body ids, and the groups reported since the previous cycle.
struct PerceptionReport {
  std::vector<model::TrackedPerson> persons;
  std::vector<ReportedGroup> groups;
};

/// Feeds `tracker` one cycle of perception, the one way social_mpc_node (bodies placed by tf) and
/// the batch tool's navigation (bodies placed by the perception frame) both do: each tracked
/// person at their body's pose and time (model::place_at_bodies: persons without a placed body
/// left out, as the planner needs a facing direction), each group at its time, then the tracker
/// forgets at `now_s` whoever perception stopped reporting.
void observe(SceneTracker& tracker, const PerceptionReport& report,
             const model::BodyLocator& locate_body, double now_s);

}  // namespace ari_social_sim::navigation
