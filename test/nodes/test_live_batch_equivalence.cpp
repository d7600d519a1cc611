// Issue 14: a batch run is what a user gets live. The same scenario and seed run through the
// in-process engine (scenario::Episode) and through a "live chain": the cores composed as the
// nodes compose them, with what the nodes exchange converted to the messages they exchange and
// back, step by step without a roscore. Every step, the world states, the perception frames and
// the navigation commands of both must be the same.
//
// The live chain, in the order of one world step (docs/ARCHITECTURE.md, section 2):
// - world_node: Simulation::step, then /sim/world_state (to_msg), tf map -> odom ->
//   base_footprint, /mobile_base_controller/odom and /joint_states;
// - hri_perception_node: the world state as received (from_msg), its ~max_rate gate (RateGate),
//   PerceptionPipeline, the frame's ROS4HRI tf frames into a tf buffer, /humans/persons/tracked
//   and each person's body_id;
// - group_detection_node (its 20 Hz timer on /clock, which core::SimTimer runs as roscpp does):
//   the tracked persons at their body_<id> frames from tf (body_placement, group_candidates_of),
//   GroupPerception, the groups as /humans/interactions/groups messages;
// - social_mpc_node: the groups received, then its timer: NavigationSession::control with ARI as
//   MeasuredAri measures it (tf, odometry, joint states) and the persons at their body frames
//   from tf; its commands as cmd_vel and head messages (to_msgs);
// - world_node applies them (the twist, head_pan_target) before its next step;
// - dialogue_node: the dialogue core on its world stage (scenario::WorldSpeechStage, voicing as
//   world_node's /sim/say does) following the world state as received (from_msg), what it
//   publishes of utterances and outcomes as the messages scenario_node reads;
// - the script (scenario::ScriptRunner) on what the step produced, its commands through the
//   world's request API (what world_node's services call, with the fields the services carry)
//   and the navigation session (what social_mpc_node's action callbacks call, a move_base goal as
//   the message scenario_node sends). Its observations are built as the engine builds them.

#include <gtest/gtest.h>
#include <tf2_ros/buffer.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "ari_social_sim/audio/world_audio.hpp"
#include "ari_social_sim/core/sim_timer.hpp"
#include "ari_social_sim/engine/episode.hpp"
#include "ari_social_sim/navigation/navigation_session.hpp"
#include "ari_social_sim/perception/candidate_matches.hpp"
#include "ari_social_sim/perception/group_candidates.hpp"
#include "ari_social_sim/scenario/group_memory.hpp"
#include "ari_social_sim/world/service_requests.hpp"
#include "dialogue_conversions/dialogue.hpp"
#include "navigation_conversions/measured_ari.hpp"
#include "navigation_conversions/navigation_msgs.hpp"
#include "node_support/hri_ids.hpp"
#include "perception_conversions/hri_messages.hpp"
#include "perception_conversions/perceived_persons.hpp"
#include "world_conversions/ari_base.hpp"
#include "world_conversions/world_state.hpp"

namespace ari_social_sim::nodes {
namespace {

const std::string kSource = ARI_SOURCE_DIR;

const engine::EpisodeConfig& episode_config() {
  static const engine::EpisodeConfig config = engine::EpisodeConfig::load(kSource + "/config");
  return config;
}

// What ros::Time::now() gives a node while world_node's /clock is at `time_s`.
double clock_s(double time_s) {
  return ros::Time(time_s).toSec();
}

// The nodes of the suite composed without ROS transport between them.
class LiveChain {
 public:
  LiveChain(const scenario::Scenario& scenario, uint64_t seed, const engine::EpisodeConfig& config)
      : scenario_(scenario),
        config_(config),
        perception_(seeded(config.perception, seed)),
        perception_gate_(config.perception_max_rate_hz),
        group_timer_(config.group_detection_rate_hz),
        group_detection_(perception_.config().groups),
        measured_(input_counters_),
        session_(config.navigation),
        dialogue_run_(engine::dialogue_run_for(scenario.script, config.dialogue_run)),
        believed_groups_(config.group_timeout_s),
        runner_(scenario, seed, config.dialogue.get()),
        commands_(*this) {
    world::Scene scene = scenario.scene;
    scene.seed = seed;
    world_ = world::build_simulation(scene, config.simulation);
    world_->set_conversation_lines(config.conversation_lines);  // as world_node installs them
    // /map, latched, as hri_perception_node and social_mpc_node receive it.
    const model::OccupancyGrid map =
        world::rasterize_static_map(scene.world, config.simulation.map_resolution_m);
    const nav_msgs::OccupancyGrid map_msg = to_msg(map, kMapFrame, 0.0);
    perception_.set_sight_map(from_msg(map_msg));
    session_.set_map(from_msg(map_msg));
    tf_.setTransform(map_to_odom(0.0), "world_node", /*is_static=*/true);
    dialogue_run_.seed = seed;
    stage_ = engine::in_process_speech_stage(
        *world_, engine::dialogue_cast(dialogue_run_, *config.dialogue, *world_, scenario));
    dialogue_ = std::make_unique<dialogue::SpokenDialogue>(*config.dialogue, *config.nlu,
                                                           dialogue_run_, *stage_);
  }

  void step() {
    world_->step();
    publish_world();
    perceive();
    detect_groups();
    navigate();
    converse();
    run_script();
  }

  bool finished() const { return runner_.finished(); }
  const world::WorldSnapshot& snapshot() const { return snapshot_; }
  const perception::PerceptionFrame* perception_frame() const { return frame_; }
  const std::vector<navigation::BaseCommand>& navigation_commands() const { return sent_; }
  const scenario::ScriptRunner& runner() const { return runner_; }

 private:
  // The script's commands as scenario_node sends them and the nodes carry them out.
  class Commands : public scenario::Commands {
   public:
    explicit Commands(LiveChain& chain) : chain_(chain) {}

    void say(const scenario::AgentRef& speaker, const std::string& act,
             const std::string& text) override {
      if (speaker.is_ari()) {
        const std::string refused = chain_.dialogue_->request_robot(text, 0.0);  // /tts
        if (!refused.empty()) {
          throw core::RequestError("/tts: " + refused);
        }
        return;
      }
      chain_.world_->say(speaker.human_id, act, text);  // /sim/say
    }
    void set_human_goal(model::ObjectId human, const core::Pose2& goal) override {
      chain_.world_->set_human_goal(human, from_msg(to_msg(goal)));  // /sim/set_goal
    }
    void navigate(const core::Pose2& goal) override {
      cancel_navigation();
      // move_base: the goal as scenario_node sends it, as social_mpc_node reads it.
      const geometry_msgs::PoseStamped target =
          map_goal_msg(goal, ros::Time(chain_.snapshot_.time_s));
      chain_.request(
          navigation::PoseTarget{navigation::planar_goal(goal_request_of(target), "target_pose.")});
    }
    void approach(const std::string& person_id, bool join_group) override {
      cancel_navigation();
      if (join_group) {
        chain_.request(navigation::GroupOfPersonTarget{person_id});
      } else {
        chain_.request(navigation::PersonTarget{person_id});
      }
    }
    void fail_navigation(const std::string& reason) override {
      cancel_navigation();
      chain_.navigation_status_ = {scenario::NavigationState::kFailed, reason};
    }
    void cancel_navigation() override {
      if (chain_.goal_ != 0) {
        chain_.apply(chain_.session_.cancel(chain_.goal_));
      }
      chain_.goal_ = 0;
      chain_.navigation_status_ = {};
    }
    void add_human(const world::HumanSpec& spec) override {
      // /sim/spawn_human with the fields scenario_node fills, then /sim/set_goal and
      // /sim/set_gaze_targets.
      const world::SpawnHumanRequest request{spec.id,
                                             spec.name,
                                             spec.role,
                                             from_msg(to_msg(spec.pose)),
                                             static_cast<float>(spec.age_years),
                                             model::to_string(spec.gender),
                                             spec.mask,
                                             model::to_string(spec.emotion)};
      const model::ObjectId id = chain_.world_->add_human(request.spec()).id();
      if (spec.goal) {
        set_human_goal(id, *spec.goal);
      }
      if (spec.gaze) {
        world::GazeTargetsRequest gaze;
        for (const world::GazeTarget& target : spec.gaze->targets) {
          gaze.targets.push_back(target.id);
          gaze.probabilities.push_back(target.probability);
        }
        gaze.mean_duration_s = spec.gaze->mean_duration_s;
        chain_.world_->set_human_gaze(id, gaze.model());
      }
    }
    void remove_human(model::ObjectId human) override { chain_.world_->remove_human(human); }
    void create_group(const world::GroupSpec& spec) override { chain_.world_->add_group(spec); }
    void create_walking_group(const world::WalkingGroupSpec& spec) override {
      chain_.world_->add_walking_group(spec);
    }
    void add_group_members(model::ObjectId group,
                           const std::vector<model::ObjectId>& members) override {
      chain_.world_->add_group_members(group, members);
    }
    void set_group_centre(model::ObjectId group, const Eigen::Vector2d& centre) override {
      chain_.world_->set_group_centre(group, centre);
    }
    void set_group_arrangement(model::ObjectId group, model::Arrangement arrangement,
                               std::optional<double> heading_rad) override {
      chain_.world_->set_group_arrangement(group, arrangement, heading_rad);
    }
    void leave_group(model::ObjectId agent) override { chain_.world_->leave_group(agent); }
    void set_posture(model::ObjectId human, world::Posture posture) override {
      // /sim/set_posture, with the posture's name as scenario_node sends it.
      chain_.world_->set_human_posture(human,
                                       world::requested_posture(world::posture_name(posture)));
    }

   private:
    LiveChain& chain_;
  };

  static perception::PerceptionConfig seeded(perception::PerceptionConfig config, uint64_t seed) {
    config.seed = seed;
    return config;
  }

  // world_node after a step.
  void publish_world() {
    snapshot_ = world::WorldSnapshot::of(*world_);
    state_msg_ = to_msg(snapshot_, kMapFrame);
    const double stamp_s = state_msg_.header.stamp.toSec();
    if (snapshot_.ari) {
      tf_.setTransform(odom_to_base(snapshot_.ari->pose, stamp_s), "world_node");
      measured_.take(to_odometry(*snapshot_.ari, stamp_s));
      measured_.take(joint_states_of(*snapshot_.ari, stamp_s));
    }
  }

  // hri_perception_node on /sim/world_state.
  void perceive() {
    frame_ = nullptr;
    ASSERT_FALSE(input_problem(state_msg_).has_value());
    if (!perception_gate_.take(state_msg_.header.stamp.toSec())) {
      return;
    }
    frame_ = &perception_.update(from_msg(state_msg_));
    const HriFrameMessages messages = hri_frame_messages(
        *frame_, perception::person_links(*frame_), true, perception_.config().human_model,
        state_msg_.header.stamp, kBaseFrame, kMapFrame);
    for (const geometry_msgs::TransformStamped& transform : messages.transforms) {
      tf_.setTransform(transform, "hri_perception_node");
    }
    // What PerceivedPersons follows: the list, and each person's latched body_id.
    tracked_.clear();
    for (const std::string& id : messages.persons_tracked.ids) {
      ASSERT_TRUE(is_valid_hri_id(id));
      const auto person =
          std::find_if(frame_->persons.begin(), frame_->persons.end(),
                       [&](const perception::PersonReport& p) { return p.person_id == id; });
      tracked_.push_back({id, person->body_id});
    }
    has_tracked_list_ = true;
    // What scenario_node's HeardSpeech keeps of each voice's /humans/voices/<id>/speech.
    for (const perception::PerceivedVoice& voice : frame_->voices) {
      for (const perception::SpeechResult& result : voice.speech) {
        const LiveSpeech speech = speech_msg(result, "en-GB", state_msg_.header);
        if (!speech.final.empty()) {
          transcripts_.push_back({voice.voice_id, speech.final, speech.confidence});
        }
      }
    }
  }

  // The persons tracked, each at their body frame in the map from tf (social_mpc_node).
  model::TrackedPersons tracked_persons() const {
    return {tracked_,
            [this](const std::string& body_id) { return body_placement(tf_, kMapFrame, body_id); }};
  }

  // group_detection_node's timer (roscpp's, on /clock: core::SimTimer), then social_mpc_node's
  // /humans/interactions/groups.
  void detect_groups() {
    const double now_s = clock_s(snapshot_.time_s);
    groups_detected_ = group_timer_.due(now_s) && has_tracked_list_;
    if (!groups_detected_) {
      return;
    }
    const model::TrackedPersons persons{tracked_, [&](const std::string& body_id) {
                                          return fresh_body_placement(tf_, kMapFrame, body_id,
                                                                      now_s);
                                        }};
    group_detection_.update(perception::group_candidates_of(persons), groups_);
    std_msgs::Header header;
    header.stamp = ros::Time(now_s);
    header.frame_id = kMapFrame;
    for (const perception::PerceivedGroup& group : groups_) {
      const Group msg = group_msg(group, header);
      session_.receive_group({msg.group_id, msg.header.stamp.toSec(), msg.members});
      believed_groups_.report(msg.group_id, msg.header.stamp.toSec(), msg.members);
    }
  }

  navigation::SessionInputs session_inputs() const {
    return {clock_s(snapshot_.time_s), measured_.observe(tf_), tracked_persons()};
  }

  // social_mpc_node's timer.
  void navigate() {
    sent_.clear();
    apply(session_.control(session_inputs()));
  }

  // social_mpc_node's action callbacks.
  void request(const navigation::NavigationTarget& target) {
    const navigation::SessionOutput out = session_.request(target, session_inputs());
    goal_ = session_.newest_goal();
    apply(out);
  }

  // What social_mpc_node sends, as world_node applies it; the goal as the script's client sees it.
  void apply(const navigation::SessionOutput& out) {
    for (const navigation::GoalChange& change : out.goals) {
      if (change.goal == goal_) {
        navigation_status_ = engine::as_seen_by_the_script(change.status);
      }
    }
    for (const navigation::BaseCommand& command : out.commands) {
      const CommandMessages messages =
          to_msgs(command, ros::Time(snapshot_.time_s), config_.navigation.navigator.rate_hz);
      world_->command_ari_twist(messages.twist.linear.x, messages.twist.angular.z);
      if (messages.head) {
        world_->command_ari_head_pan(*head_pan_target(*messages.head));
      }
      sent_.push_back(command);
    }
  }

  // dialogue_node in world mode, and what scenario_node hears of it on /sim/dialogue/utterances
  // and /sim/dialogue/outcome.
  void converse() {
    stage_->follow(from_msg(state_msg_));
    dialogue_->tick();
    const dialogue::SpokenDialogueEvents events = dialogue_->take_events();
    for (const dialogue::UtteranceEvent& event : events.utterances) {
      const DialogueUtterance msg =
          to_msg(dialogue_->live().env().transcript()[event.index], event);
      if (msg.speaker != dialogue::kRobot) {
        heard_.push_back(from_msg(msg.heard));
      }
    }
    for (const dialogue::OutcomeEvent& outcome : events.outcomes) {
      dialogue_end_ = from_msg(to_msg(outcome));
    }
  }

  // scenario_node on /sim/world_state.
  void run_script() {
    scenario::Observations observations;
    observations.world = from_msg(state_msg_);
    observations.navigation = navigation_status_;
    if (frame_ != nullptr) {
      identities_.update(observations.world, scenario::sightings_of(*frame_));
    }
    observations.person_ids = identities_.person_ids();
    observations.perceived_groups =
        believed_groups_.believed_at(observations.world.time_s, identities_);
    observations.heard = std::move(heard_);
    heard_.clear();
    observations.transcripts = std::move(transcripts_);
    transcripts_.clear();
    observations.dialogue_end = dialogue_end_;
    runner_.update(observations, commands_);
  }

  const scenario::Scenario& scenario_;
  const engine::EpisodeConfig& config_;
  std::unique_ptr<world::Simulation> world_;
  world::WorldSnapshot snapshot_;
  WorldState state_msg_;
  std::vector<perception::VoiceTranscript>
      transcripts_;  // final transcripts since the script last ran
  tf2_ros::Buffer tf_;
  perception::PerceptionPipeline perception_;
  perception::RateGate perception_gate_;
  const perception::PerceptionFrame* frame_{nullptr};
  core::SimTimer group_timer_;
  bool groups_detected_{false};
  bool has_tracked_list_{false};
  std::vector<model::TrackedPerson> tracked_;
  perception::GroupPerception group_detection_;
  std::vector<perception::PerceivedGroup> groups_;
  InputCounters input_counters_{"live_chain"};
  MeasuredAri measured_;
  navigation::NavigationSession session_;
  navigation::GoalId goal_{0};
  scenario::NavigationStatus navigation_status_;
  std::vector<navigation::BaseCommand> sent_;
  dialogue::DialogueRunConfig dialogue_run_;
  std::unique_ptr<world_speech::WorldSpeechStage> stage_;
  std::unique_ptr<dialogue::SpokenDialogue> dialogue_;
  std::vector<dialogue::Perception> heard_;  // since the script last ran
  std::optional<scenario::DialogueEnd> dialogue_end_;
  scenario::PersonIdentities identities_;
  scenario::GroupMemory believed_groups_;
  scenario::ScriptRunner runner_;
  Commands commands_;
};

// The largest difference found so far between the engine and the live chain, per kind.
struct Deviations {
  double world{0.0};
  double perception{0.0};
  double commands{0.0};
};

// Positions and angles equal to this (m, rad, m/s, rad/s): the message conversions between the
// nodes carry doubles but turn headings into quaternions and back (tf, move_base goals), and the
// clock into nanoseconds.
constexpr double kTolerance = 1e-12;

void compare_pose(const core::Pose2& engine, const core::Pose2& live, double& deviation) {
  deviation = std::max({deviation, (engine.position - live.position).cwiseAbs().maxCoeff(),
                        std::abs(core::angle_difference(engine.theta, live.theta))});
}

void compare_worlds(const world::WorldSnapshot& engine, const world::WorldSnapshot& live,
                    double& deviation) {
  ASSERT_EQ(engine.step, live.step);
  ASSERT_EQ(engine.time_s, live.time_s);
  ASSERT_EQ(engine.ari.has_value(), live.ari.has_value());
  if (engine.ari) {
    compare_pose(engine.ari->pose, live.ari->pose, deviation);
    deviation = std::max({deviation, std::abs(engine.ari->linear_mps - live.ari->linear_mps),
                          std::abs(engine.ari->angular_rps - live.ari->angular_rps),
                          std::abs(engine.ari->head_pan_rad - live.ari->head_pan_rad)});
    ASSERT_EQ(engine.ari->speech.content, live.ari->speech.content);
  }
  ASSERT_EQ(engine.humans.size(), live.humans.size());
  for (size_t i = 0; i < engine.humans.size(); ++i) {
    ASSERT_EQ(engine.humans[i].id, live.humans[i].id);
    compare_pose(engine.humans[i].pose, live.humans[i].pose, deviation);
    deviation = std::max(
        deviation,
        (engine.humans[i].velocity_mps - live.humans[i].velocity_mps).cwiseAbs().maxCoeff());
    ASSERT_EQ(engine.humans[i].gaze.target, live.humans[i].gaze.target);
    ASSERT_EQ(engine.humans[i].speech.content, live.humans[i].speech.content);
  }
  ASSERT_EQ(engine.groups.size(), live.groups.size());
  for (size_t i = 0; i < engine.groups.size(); ++i) {
    ASSERT_EQ(engine.groups[i].members, live.groups[i].members);
  }
}

void compare_frames(const perception::PerceptionFrame* engine,
                    const perception::PerceptionFrame* live, double& deviation) {
  ASSERT_EQ(engine == nullptr, live == nullptr);
  if (engine == nullptr) {
    return;
  }
  deviation = std::max(deviation, std::abs(engine->time_s - live->time_s));
  ASSERT_EQ(engine->bodies.size(), live->bodies.size());
  for (size_t i = 0; i < engine->bodies.size(); ++i) {
    ASSERT_EQ(engine->bodies[i].body_id, live->bodies[i].body_id);
    ASSERT_EQ(engine->bodies[i].person_id, live->bodies[i].person_id);
    compare_pose(engine->bodies[i].X_map_body, live->bodies[i].X_map_body, deviation);
  }
  ASSERT_EQ(engine->faces.size(), live->faces.size());
  for (size_t i = 0; i < engine->faces.size(); ++i) {
    ASSERT_EQ(engine->faces[i].face_id, live->faces[i].face_id);
    ASSERT_EQ(engine->faces[i].person_id, live->faces[i].person_id);
    compare_pose(engine->faces[i].X_map_face, live->faces[i].X_map_face, deviation);
  }
  ASSERT_EQ(engine->voices.size(), live->voices.size());
  for (size_t i = 0; i < engine->voices.size(); ++i) {
    ASSERT_EQ(engine->voices[i].voice_id, live->voices[i].voice_id);
    deviation = std::max(
        deviation, (engine->voices[i].position - live->voices[i].position).cwiseAbs().maxCoeff());
  }
  ASSERT_EQ(engine->persons.size(), live->persons.size());
  for (size_t i = 0; i < engine->persons.size(); ++i) {
    ASSERT_EQ(engine->persons[i].person_id, live->persons[i].person_id);
    ASSERT_EQ(engine->persons[i].tracked, live->persons[i].tracked);
    ASSERT_EQ(engine->persons[i].body_id, live->persons[i].body_id);
    ASSERT_EQ(engine->persons[i].face_id, live->persons[i].face_id);
  }
}

void compare_commands(const std::vector<navigation::BaseCommand>& engine,
                      const std::vector<navigation::BaseCommand>& live, double& deviation) {
  ASSERT_EQ(engine.size(), live.size());
  for (size_t i = 0; i < engine.size(); ++i) {
    ASSERT_EQ(engine[i].pan_rad.has_value(), live[i].pan_rad.has_value());
    deviation = std::max({deviation, std::abs(engine[i].linear_mps - live[i].linear_mps),
                          std::abs(engine[i].angular_rps - live[i].angular_rps)});
    if (engine[i].pan_rad) {
      deviation = std::max(deviation, std::abs(*engine[i].pan_rad - *live[i].pan_rad));
    }
  }
}

struct Run {
  std::string scenario;
  uint64_t seed;
  double step_s{0.05};  // world_node's ~step
};

class LiveBatchEquivalence : public ::testing::TestWithParam<Run> {};

TEST_P(LiveBatchEquivalence, SameWorldsFramesAndCommandsAtEveryStep) {
  const scenario::Scenario scenario =
      scenario::load_scenario_file(kSource + "/scenarios/" + GetParam().scenario + ".yaml");
  const uint64_t seed = GetParam().seed;
  engine::EpisodeConfig config = episode_config();
  config.simulation.step_s = GetParam().step_s;
  engine::Episode engine(scenario, seed, config);
  LiveChain live(scenario, seed, config);
  Deviations most;
  int steps = 0, frames = 0, commands = 0;
  while (!engine.finished() || !live.finished()) {
    ASSERT_EQ(engine.finished(), live.finished()) << "at step " << steps;
    engine.step();
    live.step();
    ++steps;
    SCOPED_TRACE("step " + std::to_string(steps) + " at " +
                 std::to_string(engine.snapshot().time_s) + " s");
    ASSERT_NO_FATAL_FAILURE(compare_worlds(engine.snapshot(), live.snapshot(), most.world));
    ASSERT_NO_FATAL_FAILURE(
        compare_frames(engine.perception_frame(), live.perception_frame(), most.perception));
    ASSERT_NO_FATAL_FAILURE(
        compare_commands(engine.navigation_commands(), live.navigation_commands(), most.commands));
    ASSERT_LE(most.world, kTolerance);
    ASSERT_LE(most.perception, kTolerance);
    ASSERT_LE(most.commands, kTolerance);
    frames += engine.perception_frame() != nullptr;
    commands += static_cast<int>(engine.navigation_commands().size());
  }
  ASSERT_TRUE(engine.runner().outcome().has_value());
  EXPECT_EQ(engine.runner().outcome()->success, live.runner().outcome()->success);
  EXPECT_EQ(engine.runner().outcome()->reason, live.runner().outcome()->reason);
  std::printf(
      "%s seed %lu: %d steps compared (%d perception frames, %d navigation commands), %s; "
      "largest differences: world %.1e, perception %.1e, commands %.1e\n",
      GetParam().scenario.c_str(), static_cast<unsigned long>(seed), steps, frames, commands,
      engine.runner().outcome()->reason.c_str(), most.world, most.perception, most.commands);
  // The runs are long enough to matter: the script ran to its end, ARI moved.
  EXPECT_GT(commands, 50);
}

// Issue 30: the audio of a run is the same live and in batch. audio_node's WorldAudio follows the
// live chain's /sim/world_state as received (from_msg); the batch tools' follows the engine's
// snapshots. Every sample of every channel must be equal.
TEST(LiveBatchAudio, AudioNodeHearsTheSamplesTheBatchToolsWrite) {
  const scenario::Scenario scenario =
      scenario::load_scenario_file(kSource + "/scenarios/group_discussion.yaml");
  const engine::EpisodeConfig config = episode_config();
  engine::Episode engine(scenario, 1, config);
  LiveChain live(scenario, 1, config);
  const std::vector<audio::Wall> walls = audio::walls_of(scenario.scene.world);
  audio::WorldAudio batch_audio({}, walls, 1, std::make_shared<audio::SpeechSynthesizer>());
  audio::WorldAudio node_audio({}, walls, 1, std::make_shared<audio::SpeechSynthesizer>());
  size_t chunks = 0, differing_samples = 0;
  double loudest = 0.0;
  while (!engine.finished()) {
    engine.step();
    live.step();
    batch_audio.observe(engine.snapshot());
    node_audio.observe(from_msg(to_msg(live.snapshot(), kMapFrame)));
    const std::vector<audio::ArrayChunk> batch = batch_audio.chunks_until(engine.snapshot().time_s);
    const std::vector<audio::ArrayChunk> node = node_audio.chunks_until(live.snapshot().time_s);
    ASSERT_EQ(batch.size(), node.size());
    for (size_t i = 0; i < batch.size(); ++i, ++chunks) {
      for (size_t c = 0; c < batch[i].channels.size(); ++c) {
        for (size_t k = 0; k < batch[i].channels[c].size(); ++k) {
          if (batch[i].channels[c][k] != node[i].channels[c][k] && differing_samples++ == 0) {
            std::printf("first difference: chunk %zu channel %zu sample %zu at %.3f s: %d %d\n",
                        chunks, c, k, engine.snapshot().time_s, batch[i].channels[c][k],
                        node[i].channels[c][k]);
          }
          loudest = std::max(loudest, std::abs(double(batch[i].channels[c][k])));
        }
      }
    }
  }
  std::printf("%zu chunks of 6 channels compared, %zu samples differ, loudest %.0f\n", chunks,
              differing_samples, loudest);
  EXPECT_GT(chunks, 400u);     // the whole run, about 30 s
  EXPECT_GT(loudest, 3000.0);  // with voices in it, not only noise
  EXPECT_EQ(differing_samples, 0u);
}

INSTANTIATE_TEST_SUITE_P(ShippedScenarios, LiveBatchEquivalence,
                         ::testing::Values(Run{"group_discussion", 1}, Run{"join_group", 1},
                                           Run{"join_group", 7}, Run{"corridor", 1},
                                           Run{"waiting_room", 1},
                                           // Perception (30 Hz) and group detection (20 Hz)
                                           // then run on different steps.
                                           Run{"join_group", 1, 0.02}),
                         [](const ::testing::TestParamInfo<Run>& info) {
                           const int step_ms = static_cast<int>(info.param.step_s * 1000 + 0.5);
                           return info.param.scenario + "_seed" + std::to_string(info.param.seed) +
                                  "_step" + std::to_string(step_ms) + "ms";
                         });

}  // namespace
}  // namespace ari_social_sim::nodes
