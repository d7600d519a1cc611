#include "ari_social_sim/navigation/navigation_session.hpp"

#include <cmath>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/number_text.hpp"
#include "ari_social_sim/navigation/policy_controller.hpp"

namespace ari_social_sim::navigation {
namespace {

// A sim time may be a hair below the multiple of a period it stands for, in doubles: a call falls
// in the period it is meant for.
constexpr double kPeriodSlack = 1e-6;  // of a period

// True at the first call in each period of `rate_hz` counted from sim time 0, and after time went
// back (a world reset); `last` keeps the period of the last such call.
bool first_in_period(double now_s, double rate_hz, std::optional<int64_t>& last) {
  const auto period = static_cast<int64_t>(std::floor(now_s * rate_hz + kPeriodSlack));
  if (last == period) {
    return false;
  }
  last = period;
  return true;
}

// What the session is told is rounded to a microsecond, a micrometre and a microradian (headings
// into [-pi, pi) first): far below what ARI's sensors resolve, and far above the rounding of the
// ways it is told. Live, headings reach social_mpc_node as quaternions (tf, move_base goals) and
// bodies through ARI's frame, an ulp or two off what the batch engine reads in the perception
// frame, and a script's goal heading of 3.1416 comes back from move_base's quaternion as
// -3.14158...; unrounded, such differences changed the first command of join_group (seed 1) by
// 1e-7 m/s and grew from there. Rounded, both plan on the same numbers.
constexpr double kResolution = 1e-6;

double rounded(double value) {
  return std::round(value / kResolution) * kResolution;
}

core::Pose2 rounded(const core::Pose2& pose) {
  return {{rounded(pose.position.x()), rounded(pose.position.y())},
          rounded(core::wrap_angle(pose.theta))};
}

NavigationTarget rounded(const NavigationTarget& target) {
  if (const auto* pose = std::get_if<PoseTarget>(&target)) {
    return PoseTarget{rounded(pose->pose)};
  }
  return target;
}

SessionInputs rounded(const SessionInputs& inputs) {
  SessionInputs out;
  out.now_s = rounded(inputs.now_s);
  // A rogue transform (map -> odom at 1e300) places ARI nowhere rather than there.
  if (inputs.robot && model::pose_problem(inputs.robot->pose).empty()) {
    out.robot = inputs.robot;
    out.robot->pose = rounded(out.robot->pose);
  }
  out.perception.persons = inputs.perception.persons;
  out.perception.locate_body = [locate =
                                    inputs.perception.locate_body](const std::string& body_id) {
    std::optional<model::BodyPlacement> body = locate(body_id);
    if (body) {
      body = model::BodyPlacement{rounded(body->stamp_s), rounded(body->pose)};
    }
    return body;
  };
  return out;
}

}  // namespace

NavigationSession::NavigationSession(const NavigationConfig& config, std::shared_ptr<Policy> policy)
    : config_(config),
      tracker_(config.scene),
      policy_(std::move(policy)),
      control_rate_hz_(config.navigator.rate_hz) {
  if (!policy_ && !config.navigator.policy_file.empty()) {
    policy_ = std::make_shared<MlpPolicy>(MlpPolicy::load_file(config.navigator.policy_file));
  }
  if (policy_) {
    control_rate_hz_ = policy_->control_rate_hz();
  }
}

SessionOutput NavigationSession::set_map(const model::OccupancyGrid& map) {
  SessionOutput out;
  if (pursued_) {
    end_pursued({GoalState::kAborted, "the map changed while navigating"}, out);
  }
  if (policy_) {
    controller_ = std::make_unique<PolicyController>(config_, map, policy_);
    navigator_ = nullptr;
  } else {
    auto navigator = std::make_unique<Navigator>(config_, map);
    navigator_ = navigator.get();
    controller_ = std::move(navigator);
  }
  return out;
}

void NavigationSession::receive_group(ReportedGroup group) {
  group.stamp_s = rounded(group.stamp_s);
  received_groups_.push_back(std::move(group));
}

SessionOutput NavigationSession::request(const NavigationTarget& target,
                                         const SessionInputs& told) {
  const SessionInputs inputs = rounded(told);
  SessionOutput out;
  follow_clock(inputs.now_s, out);
  if (waiting_) {
    out.goals.push_back(
        {waiting_->id,
         {GoalState::kRejected, "preempted by a new goal before its target was perceived"}});
  }
  waiting_ = WaitingGoal{next_goal_++, rounded(target), inputs.now_s + kTargetWait_s};
  out.goals.push_back({waiting_->id, {GoalState::kPending, ""}});
  look_at_perception(inputs);
  try_waiting_goal(inputs, out);
  return out;
}

SessionOutput NavigationSession::cancel(GoalId goal) {
  SessionOutput out;
  const GoalStatus canceled{GoalState::kCanceled, "canceled by the client"};
  if (waiting_ && waiting_->id == goal) {
    out.goals.push_back({goal, canceled});
    waiting_.reset();
  }
  if (pursued_ == goal) {
    controller_->cancel();
    end_pursued(canceled, out);
  }
  return out;
}

SessionOutput NavigationSession::control(const SessionInputs& told) {
  SessionOutput out;
  follow_clock(rounded(told.now_s), out);
  const double rate_hz = control_rate_hz_;
  const bool look = first_in_period(told.now_s, kLooksPerCycle * rate_hz, last_look_);
  const bool cycle = first_in_period(told.now_s, rate_hz, last_cycle_);
  if (!look && !cycle) {
    return out;
  }
  const SessionInputs inputs = rounded(told);
  // People are followed all the time, so that a goal naming someone finds them known already;
  // those perception stopped reporting are let go.
  look_at_perception(inputs);
  if (!cycle) {
    return out;
  }
  try_waiting_goal(inputs, out);
  if (!pursued_ || !inputs.robot) {
    return out;
  }
  const NavigatorStep step =
      controller_->update(inputs.now_s, *inputs.robot, tracker_.scene(inputs.now_s));
  out.step = step;
  if (step.state == NavigationState::kSucceeded) {
    end_pursued({GoalState::kSucceeded, ""}, out);
  } else if (step.state == NavigationState::kAborted) {
    end_pursued({GoalState::kAborted, step.reason}, out);
  } else {
    out.commands.push_back(
        {step.command.linear_mps, step.command.angular_rps, step.command.pan_rad});
  }
  return out;
}

void NavigationSession::look_at_perception(const SessionInputs& inputs) {
  const PerceptionReport report{inputs.perception.persons, std::move(received_groups_)};
  received_groups_.clear();
  observe(tracker_, report, inputs.perception.locate_body, inputs.now_s);
}

void NavigationSession::try_waiting_goal(const SessionInputs& inputs, SessionOutput& out) {
  if (!waiting_) {
    return;
  }
  const std::string unknown = unknown_target_reason(waiting_->target, tracker_.scene(inputs.now_s));
  if (unknown.empty()) {
    const WaitingGoal goal = std::move(*waiting_);
    waiting_.reset();
    start(goal.id, goal.target, inputs, out);
  } else if (inputs.now_s >= waiting_->until_s) {
    out.goals.push_back({waiting_->id, {GoalState::kRejected, unknown}});
    waiting_.reset();
  }
}

void NavigationSession::start(GoalId id, const NavigationTarget& target,
                              const SessionInputs& inputs, SessionOutput& out) {
  try {
    if (!controller_) {
      throw core::RequestError("no map received on /map yet");
    }
    if (!inputs.robot) {
      throw core::RequestError("no transform from map to base_footprint yet");
    }
    controller_->start(target, tracker_.scene(inputs.now_s), *inputs.robot, inputs.now_s);
  } catch (const core::Error& e) {
    // The goal pursued before, if any, goes on: the navigator kept it.
    out.goals.push_back({id, {GoalState::kAborted, e.what()}});
    return;
  }
  if (pursued_) {
    // The navigator pursues the new goal now: the old one only needs its end told.
    out.goals.push_back({*pursued_, {GoalState::kCanceled, "preempted by a new goal"}});
  }
  pursued_ = id;
  out.goals.push_back({id, {GoalState::kActive, ""}});
}

void NavigationSession::follow_clock(double now_s, SessionOutput& out) {
  const std::optional<double> before_s = last_now_s_;
  last_now_s_ = now_s;
  if (!before_s || now_s >= *before_s) {
    return;
  }
  tracker_.clear();
  received_groups_.clear();
  if (waiting_) {
    waiting_->until_s = now_s + kTargetWait_s;
  }
  if (pursued_) {
    controller_->cancel();
    end_pursued({GoalState::kAborted, "sim time went back from " + core::number_text(*before_s) +
                                          " s to " + core::number_text(now_s) +
                                          " s (a world reset): the goal's progress is void"},
                out);
  }
}

void NavigationSession::end_pursued(const GoalStatus& status, SessionOutput& out) {
  out.goals.push_back({*pursued_, status});
  pursued_.reset();
  out.commands.push_back({});
}

}  // namespace ari_social_sim::navigation
