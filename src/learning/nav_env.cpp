#include "ari_social_sim/learning/nav_env.hpp"

#include <algorithm>
#include <cmath>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/core/check.hpp"
#include "ari_social_sim/core/config_check.hpp"
#include "ari_social_sim/core/config_reader.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/rng_streams.hpp"
#include "ari_social_sim/core/yaml_map.hpp"
#include "ari_social_sim/engine/ari_observation.hpp"
#include "ari_social_sim/learning/ground_truth.hpp"
#include "ari_social_sim/learning/scenario_nav_env.hpp"
#include "ari_social_sim/model/ari_limits.hpp"
#include "ari_social_sim/navigation/perception_report.hpp"
#include "ari_social_sim/navigation/signed_distance_field.hpp"
#include "ari_social_sim/perception/group_candidates.hpp"
#include "ari_social_sim/perception/tracked_persons.hpp"
#include "ari_social_sim/world/map_sensor.hpp"
#include "ari_social_sim/world/world_snapshot.hpp"
#include "ari_social_sim/world_speech/small_talk_lines.hpp"

namespace ari_social_sim::learning {
namespace {

// The environments' static map: coarser than world_node's 0.05 m, as a reset rebuilds it and
// its distance field for every episode's furniture.
constexpr double kMapResolution_m = 0.1;
// Attempts at a seed's episode before giving up: a few draws leave no free place to stand.
constexpr int kEpisodeAttempts = 10;

EpisodeType episode_type_for(const NavTaskConfig& task, uint64_t seed) {
  switch (task.task) {
    case NavTask::kGoToPose:
      return EpisodeType::kPose;
    case NavTask::kApproachPerson:
      return EpisodeType::kApproach;
    case NavTask::kJoinConversation:
      return task.conversation.group_size == 2   ? EpisodeType::kJoin2
             : task.conversation.group_size == 3 ? EpisodeType::kJoin3
                                                 : EpisodeType::kJoin4;
    case NavTask::kJoinGroup:
    case NavTask::kScenario:  // ScenarioNavEnv's
      break;
  }
  // Groups of 2, 3 and 4 in equal shares, drawn from the seed.
  const uint64_t draw = core::rng_for(seed, core::rng_streams::kNavEpisodeType).next_u64() % 3;
  return draw == 0 ? EpisodeType::kJoin2 : draw == 1 ? EpisodeType::kJoin3 : EpisodeType::kJoin4;
}

// A join episode names its group; perception does not know group ids, so the policy is told to
// join the group of its first member, as scenario_node asks social_mpc_node.
navigation::NavigationTarget perceivable_target(const NavigationEpisode& episode) {
  if (std::holds_alternative<navigation::GroupTarget>(episode.target)) {
    return navigation::GroupOfPersonTarget{episode.exempt_people.front()};
  }
  return episode.target;
}

}  // namespace

std::shared_ptr<const NavEnvSetup> NavEnvSetup::load(const std::string& package_dir,
                                                     const std::string& task_file,
                                                     const std::string& overrides,
                                                     const std::string& overrides_source) {
  auto setup = std::make_shared<NavEnvSetup>();
  setup->task = NavTaskConfig::load_file(task_file);
  if (!overrides.empty()) {
    core::read_fields(core::YamlMap::parse(overrides, overrides_source), setup->task);
  }
  setup->task.validate();
  setup->perception =
      perception::PerceptionConfig::load_file(package_dir + "/config/perception.yaml");
  setup->perception.errors_enabled = setup->task.perception_errors;
  setup->navigation =
      navigation::NavigationConfig::load_file(package_dir + "/config/social_mpc.yaml");
  setup->worlds = EpisodeWorlds::load(package_dir + "/worlds");
  if (setup->task.task == NavTask::kScenario) {
    setup->scenario = scenario::load_scenario_file(setup->task.scenario);
    setup->episode = engine::EpisodeConfig::load(package_dir + "/config");
    setup->episode->perception.errors_enabled = setup->task.perception_errors;
  }
  if (setup->task.task == NavTask::kJoinConversation) {
    setup->conversation_lines = world_speech::SmallTalkLines::load(package_dir + "/config");
  }
  return setup;
}

ActionBounds action_bounds() {
  const model::AriLimits limits;
  ActionBounds bounds;
  bounds.low = {static_cast<float>(limits.min_linear_mps),
                static_cast<float>(-limits.max_angular_rps),
                static_cast<float>(-limits.head_pan_limit_rad)};
  bounds.high = {static_cast<float>(limits.max_linear_mps),
                 static_cast<float>(limits.max_angular_rps),
                 static_cast<float>(limits.head_pan_limit_rad)};
  return bounds;
}

int action_size(NavTask task) {
  return task == NavTask::kJoinConversation ? kConversationActionSize : kActionSize;
}

const char* action_name(int index) {
  return index < kActionSize ? kActionNames[index] : kSpeakName;
}

float checked_speak(float speak) {
  if (!std::isfinite(speak)) {
    throw core::RequestError(std::string("learning: action[") + std::to_string(kActionSize) +
                             "] (" + kSpeakName + "): expected a finite number in [0, 1], got " +
                             std::to_string(speak));
  }
  return std::clamp(speak, 0.0f, 1.0f);
}

std::array<float, kActionSize> checked_action(const float* action, const ActionBounds& bounds) {
  std::array<float, kActionSize> command{};
  for (int i = 0; i < kActionSize; ++i) {
    if (!std::isfinite(action[i])) {
      throw core::RequestError(std::string("learning: action[") + std::to_string(i) + "] (" +
                               kActionNames[i] + "): expected a finite number, got " +
                               std::to_string(action[i]));
    }
    command[i] = std::clamp(action[i], bounds.low[i], bounds.high[i]);
  }
  return command;
}

NavEnv::NavEnv(std::shared_ptr<const NavEnvSetup> setup)
    : setup_(std::move(setup)),
      footprint_(navigation::FootprintModel::covering(model::AriFootprint{},
                                                      setup_->navigation.mpc.footprint_circles)),
      goal_finder_(setup_->navigation.goal_finder, footprint_,
                   setup_->navigation.mpc.personal_space),
      observation_(setup_->task.observation),
      bounds_(action_bounds()),
      tracker_(setup_->navigation.scene) {}

NavEnv::~NavEnv() = default;

navigation::RobotObservation NavEnv::robot() const {
  return engine::observe_ari(*episode_.simulation->ari());
}

void NavEnv::reset(std::optional<uint64_t> seed, float* observation) {
  const uint64_t episode_seed = seeds_.take(seed);
  const NavTaskConfig& task = setup_->task;
  const EpisodeType type = episode_type_for(task, episode_seed);
  for (int attempt = 0;; ++attempt) {
    episode_ = make_episode(type, attempt, episode_seed, setup_->worlds);
    map_ = world::rasterize_static_map(episode_.simulation->world(), kMapResolution_m);
    sdf_ = navigation::signed_distance_field(map_);
    const navigation::PerceivedScene truth =
        true_scene(*episode_.simulation, setup_->navigation.scene.group_stride_m);
    const navigation::GoalSearch search =
        goal_finder_.find(episode_.target, truth, sdf_, episode_.simulation->ari()->pose());
    if (const auto* goal = std::get_if<navigation::Goal>(&search)) {
      true_goal_ = *goal;
      break;
    }
    if (attempt + 1 == kEpisodeAttempts) {
      throw core::RequestError("learning: episode seed " + std::to_string(episode_seed) +
                               " has no place for ARI's goal in " +
                               std::to_string(kEpisodeAttempts) + " attempts");
    }
  }
  walk_rng_ = core::Rng(core::rng_for(episode_seed, core::rng_streams::kNavWalkers).next_u64());
  if (task.walkers > 0) {
    add_walkers(episode_, task.walkers, walk_rng_);
  }
  episode_.time_limit_s = task.time_limit_s;
  target_ = perceivable_target(episode_);

  perception::PerceptionConfig perception = setup_->perception;
  perception.seed = episode_seed;
  perception_ = std::make_unique<perception::PerceptionPipeline>(perception);
  perception_->set_sight_map(map_);
  groups_ = std::make_unique<perception::GroupPerception>(perception.groups);
  detected_.clear();
  tracker_.clear();
  score_ = std::make_unique<SocialScore>(footprint_, setup_->navigation.mpc.personal_space,
                                         episode_.exempt_people, episode_.exempt_group,
                                         setup_->navigation.scene.group_stride_m);

  instructed_goal_ = true_goal_;
  perceived_goal_.reset();
  next_goal_update_s_ = 0.0;
  last_action_ = {};
  arrived_before_ = false;
  metrics_ = {};
  metrics_.episode_seed = episode_seed;
  start_conversation();
  perceive(world::WorldSnapshot::of(*episode_.simulation));
  place_goals(true);
  last_distance_m_ = (true_goal_->pose.position - robot().pose.position).norm();
  metrics_.distance_to_goal_m = last_distance_m_;
  metrics_.goal_perceived = perceived_goal_.has_value();
  done_ = false;
  started_ = true;
  write_observation(observation);
}

// join_conversation: the joined group talks with the shipped small talk (the other group too:
// the room is not silent), and the task follows the joined one.
void NavEnv::start_conversation() {
  conversation_.reset();
  if (setup_->task.task != NavTask::kJoinConversation) {
    return;
  }
  world::Simulation& sim = *episode_.simulation;
  sim.set_conversation_lines(setup_->conversation_lines);
  for (const world::GroupSnapshot& group : world::WorldSnapshot::of(sim).groups) {
    if (group_id(group.id) == episode_.exempt_group) {
      conversation_ =
          std::make_unique<ConversationTask>(setup_->task.conversation, group.id, group.members);
    }
  }
  ARI_CHECK(conversation_ != nullptr);  // join episodes always name their group
  metrics_.conversation = conversation_->metrics();
}

// As hri_perception_node, group_detection_node and social_mpc_node's look at perception, at
// every step: the perception frame, GCFF on its persons at their bodies, and the filtered scene.
void NavEnv::perceive(const world::WorldSnapshot& snapshot) {
  const double now_s = snapshot.time_s;
  const perception::PerceptionFrame& frame = perception_->update(snapshot);
  if (conversation_) {
    conversation_->hear(frame);
  }
  groups_->update(perception::group_candidates_of(frame), detected_);
  navigation::PerceptionReport report;
  model::TrackedPersons tracked = perception::tracked_persons_of(frame);
  report.persons = std::move(tracked.persons);
  report.groups.reserve(detected_.size());
  for (const perception::PerceivedGroup& group : detected_) {
    report.groups.push_back({group.group_id, now_s, group.members});
  }
  navigation::observe(tracker_, report, tracked.locate_body, now_s);
  scene_ = tracker_.scene(now_s);
}

// The goal finder on the perceived scene (the policy's goal) and on the truth (the reward's),
// every goal_update_period; each keeps its last goal while the target cannot be placed.
void NavEnv::place_goals(bool force) {
  const world::Simulation& sim = *episode_.simulation;
  if (!force && sim.time_s() < next_goal_update_s_ - 1e-9) {
    return;
  }
  next_goal_update_s_ = sim.time_s() + setup_->task.goal_update_period_s;
  const core::Pose2 pose = sim.ari()->pose();
  navigation::GoalSearch seen = goal_finder_.find(target_, scene_, sdf_, pose, perceived_goal_);
  if (auto* goal = std::get_if<navigation::Goal>(&seen)) {
    perceived_goal_ = std::move(*goal);
  }
  const navigation::PerceivedScene truth = true_scene(sim, setup_->navigation.scene.group_stride_m);
  navigation::GoalSearch real = goal_finder_.find(episode_.target, truth, sdf_, pose, true_goal_);
  if (auto* goal = std::get_if<navigation::Goal>(&real)) {
    true_goal_ = std::move(*goal);
  }
}

int NavEnv::observation_size() const {
  return observation_.size() +
         (setup_->task.task == NavTask::kJoinConversation ? ConversationTask::kObservationSize : 0);
}

std::vector<navigation::ObservationField> NavEnv::observation_fields() const {
  std::vector<navigation::ObservationField> fields = observation_.fields();
  if (setup_->task.task == NavTask::kJoinConversation) {
    fields.push_back(ConversationTask::field(observation_.size()));
  }
  return fields;
}

void NavEnv::write_observation(float* out) const {
  const bool perceived = perceived_goal_.has_value();
  observation_.build(robot(), scene_, perceived ? perceived_goal_ : instructed_goal_, perceived,
                     map_, out);
  if (conversation_) {
    conversation_->write_observation(out + observation_.size());
  }
}

NavStepResult NavEnv::step(const float* action, float* observation) {
  if (!started_) {
    throw core::RequestError("learning: step() before reset()");
  }
  if (done_) {
    throw core::RequestError("learning: step() after the episode ended; call reset()");
  }
  const std::array<float, kActionSize> command = checked_action(action, bounds_);
  const NavTaskConfig& task = setup_->task;
  const float speak = conversation_ ? checked_speak(action[kActionSize]) : 0.0f;
  world::Simulation& sim = *episode_.simulation;
  sim.command_ari_twist(command[0], command[1]);
  sim.command_ari_head_pan(command[2]);
  double talk_reward = conversation_ ? conversation_->act(sim, speak, task.rewards) : 0.0;
  keep_walking(episode_, walk_rng_);
  sim.step();
  const double dt = sim.config().step_s;

  const world::WorldSnapshot snapshot = world::WorldSnapshot::of(sim);
  perceive(snapshot);
  place_goals(false);
  if (conversation_) {
    talk_reward += conversation_->observe(snapshot, task.rewards);
  }

  const SocialScore::Step social = score_->add(sim, dt, task.rewards);
  const core::Pose2 pose = sim.ari()->pose();
  const double distance = (true_goal_->pose.position - pose.position).norm();
  const double heading_error = std::abs(core::angle_difference(true_goal_->pose.theta, pose.theta));
  const bool arrived = distance <= task.arrival.position_tolerance_m &&
                       heading_error <= task.arrival.heading_tolerance_rad;
  const RewardWeights& w = task.rewards;
  // join_conversation goes on after arriving, to be addressed: its arrival term counts once.
  const bool first_arrival = arrived && !arrived_before_;
  arrived_before_ = arrived_before_ || arrived;
  NavStepResult result;
  result.reward = social.reward + talk_reward + w.progress * (last_distance_m_ - distance) +
                  w.smoothness * (std::abs(command[0] - last_action_[0]) +
                                  std::abs(command[1] - last_action_[1])) +
                  (first_arrival ? w.arrival : 0.0);
  const bool finished = conversation_ ? conversation_->metrics().success : arrived;
  result.terminated = finished || (task.terminate_on_collision && social.collisions > 0);
  result.truncated = !result.terminated && sim.time_s() >= episode_.time_limit_s - 1e-9;
  last_distance_m_ = distance;
  last_action_ = command;

  // join_conversation goes on after arriving: its `arrived` is having reached the place.
  metrics_.arrived = conversation_ ? arrived_before_ : arrived;
  score_->fill(metrics_, sim.time_s());
  metrics_.distance_to_goal_m = distance;
  metrics_.goal_perceived = perceived_goal_.has_value();
  if (conversation_) {
    metrics_.conversation = conversation_->metrics();
  }
  done_ = result.terminated || result.truncated;
  if (done_ && task.task == NavTask::kJoinGroup) {
    metrics_.gcff_includes_ari = gcff_includes_ari(sim, footprint_, episode_.exempt_people) ? 1 : 0;
  }
  write_observation(observation);
  return result;
}

std::unique_ptr<Env> make_env(std::shared_ptr<const NavEnvSetup> setup) {
  if (setup->task.task == NavTask::kScenario) {
    return std::make_unique<ScenarioNavEnv>(std::move(setup));
  }
  return std::make_unique<NavEnv>(std::move(setup));
}

}  // namespace ari_social_sim::learning
