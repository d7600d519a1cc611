#pragma once

#include <map>
#include <string>
#include <vector>

#include "ari_social_sim/scenario/observations.hpp"
#include "ari_social_sim/scenario/person_identities.hpp"

namespace ari_social_sim::scenario {

/// The groups a script believes exist (scenario_node on /humans/interactions/groups, and the
/// engine on its group detections): each group as it was last reported, until it has not been
/// reported for `timeout_s` of sim time. Group detection may skip a frame or report a group late;
/// a script's condition on a group should not flicker with it.
class GroupMemory {
 public:
  /// `timeout_s` > 0 (ScenarioRunConfig::group_timeout_s, checked by its config).
  explicit GroupMemory(double timeout_s) : timeout_s_(timeout_s) {}

  /// A report of group `group_id` with these person ids, stamped `stamp_s`.
  void report(const std::string& group_id, double stamp_s, std::vector<std::string> person_ids);
  /// The groups still believed at `now_s`, by group id, their members mapped through
  /// `identities`; forgets those reported last more than the timeout before.
  std::vector<PerceivedGroup> believed_at(double now_s, const PersonIdentities& identities);

 private:
  struct Report {
    double stamp_s{0.0};
    std::vector<std::string> person_ids;
  };

  double timeout_s_;
  std::map<std::string, Report> groups_;  // by group id
};

}  // namespace ari_social_sim::scenario
