#include "scenario_status.hpp"

namespace ari_social_sim::nodes {

ScenarioStatus to_msg(const std::string& scenario_name, const scenario::ScriptRunner& runner,
                      double stamp_s) {
  ScenarioStatus msg;
  msg.header.stamp = ros::Time(stamp_s);
  msg.scenario = scenario_name;
  msg.state = runner.state();
  if (const auto& outcome = runner.outcome()) {
    msg.finished = true;
    msg.success = outcome->success;
    msg.reason = outcome->reason;
  }
  return msg;
}

}  // namespace ari_social_sim::nodes
