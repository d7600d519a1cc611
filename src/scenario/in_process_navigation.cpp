#include "ari_social_sim/scenario/in_process_navigation.hpp"

#include <algorithm>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/navigation/perception_report.hpp"
#include "ari_social_sim/scenario/ari_observation.hpp"

namespace ari_social_sim::scenario {

InProcessNavigation::InProcessNavigation(const navigation::NavigationConfig& config,
                                         const model::OccupancyGrid& map,
                                         world::Simulation& simulation)
    : config_(config), simulation_(simulation), tracker_(config.scene), navigator_(config, map) {}

void InProcessNavigation::observe(const perception::PerceptionFrame& frame,
                                  const std::vector<perception::PerceivedGroup>& groups) {
  // As social_mpc_node, with the frame in place of /humans/persons/tracked, the persons' body_id
  // and the body_<id> frames, and the groups group detection found in it.
  navigation::PerceptionReport report;
  for (const perception::PersonReport& person : frame.persons) {
    if (person.tracked) {
      report.persons.push_back({person.person_id, person.body_id});
    }
  }
  for (const perception::PerceivedGroup& group : groups) {
    report.groups.push_back({group.group_id, frame.time_s, group.members});
  }
  const auto locate_body = [&frame](const std::string& body_id) {
    std::optional<model::BodyPlacement> placement;
    const auto body =
        std::find_if(frame.bodies.begin(), frame.bodies.end(),
                     [&](const perception::PerceivedBody& b) { return b.body_id == body_id; });
    if (body != frame.bodies.end()) {
      placement = model::BodyPlacement{frame.time_s, body->X_map_body};
    }
    return placement;
  };
  navigation::observe(tracker_, report, locate_body, frame.time_s);
}

void InProcessNavigation::start(const navigation::NavigationTarget& target) {
  const double now = simulation_.time_s();
  try {
    if (simulation_.ari() == nullptr) {
      throw core::RequestError("no transform from map to base_footprint: the scene has no ARI");
    }
    navigator_.start(target, tracker_.scene(now), observe_ari(*simulation_.ari()), now);
  } catch (const core::Error& e) {
    // The previous goal stays as it was, as with an action server that rejects a new goal.
    status_ = {NavigationState::kFailed, e.what()};
    return;
  }
  status_ = {NavigationState::kActive, ""};
}

void InProcessNavigation::cancel() {
  if (status_.state == NavigationState::kActive) {
    navigator_.cancel();
    stop();
  }
  status_ = {};
}

void InProcessNavigation::fail(const std::string& reason) {
  cancel();
  status_ = {NavigationState::kFailed, reason};
}

void InProcessNavigation::control() {
  const double now = simulation_.time_s();
  if (now < next_control_s_ - 1e-9) {
    return;
  }
  next_control_s_ = now + 1.0 / config_.navigator.rate_hz;
  if (navigator_.state() != navigation::NavigationState::kActive || simulation_.ari() == nullptr) {
    return;
  }
  const navigation::NavigatorStep step =
      navigator_.update(now, observe_ari(*simulation_.ari()), tracker_.scene(now));
  if (step.state == navigation::NavigationState::kSucceeded) {
    status_ = {NavigationState::kSucceeded, ""};
    stop();
    return;
  }
  if (step.state == navigation::NavigationState::kAborted) {
    status_ = {NavigationState::kFailed, step.reason};
    stop();
    return;
  }
  simulation_.command_ari_twist(step.command.linear_mps, step.command.angular_rps);
  simulation_.command_ari_head_pan(step.command.pan_rad);
  sent_.push_back({step.command.linear_mps, step.command.angular_rps, step.command.pan_rad});
}

void InProcessNavigation::stop() {
  if (simulation_.ari() != nullptr) {
    simulation_.command_ari_twist(0.0, 0.0);
  }
  sent_.push_back({});
}

std::vector<SentCommand> InProcessNavigation::take_commands() {
  std::vector<SentCommand> taken = std::move(sent_);
  sent_.clear();
  return taken;
}

}  // namespace ari_social_sim::scenario
