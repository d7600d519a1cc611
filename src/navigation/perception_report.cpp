#include "ari_social_sim/navigation/perception_report.hpp"

namespace ari_social_sim::navigation {

void observe(SceneTracker& tracker, const PerceptionReport& report,
             const model::BodyLocator& locate_body, double now_s) {
  for (const model::PlacedPerson& person : model::place_at_bodies(report.persons, locate_body)) {
    tracker.observe_person(person.person_id, person.stamp_s, person.pose.position,
                           person.pose.theta);
  }
  for (const ReportedGroup& group : report.groups) {
    tracker.observe_group(group.group_id, group.stamp_s, group.members);
  }
  tracker.forget(now_s);
}

}  // namespace ari_social_sim::navigation
