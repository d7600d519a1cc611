// hri_perception_node: what ARI's ROS4HRI perception stack would publish about the people around
// it, computed from the world's ground truth (/sim/world_state, /map) by the perception core.
// Reads parameters, builds the core, wires topics and tf, converts at the edges.

#include <diagnostic_msgs/DiagnosticArray.h>
#include <nav_msgs/OccupancyGrid.h>
#include <ros/package.h>
#include <ros/ros.h>
#include <std_msgs/Bool.h>
#include <std_msgs/Float32.h>
#include <std_msgs/String.h>
#include <tf2_ros/transform_broadcaster.h>
#include <visualization_msgs/MarkerArray.h>

#include <map>
#include <memory>
#include <optional>

#include "ari_social_sim/WorldState.h"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/model/world_file.hpp"
#include "ari_social_sim/perception/candidate_matches.hpp"
#include "ari_social_sim/perception/per_id_store.hpp"
#include "ari_social_sim/perception/perception_pipeline.hpp"
#include "ari_social_sim/perception/perception_run_config.hpp"
#include "ari_social_sim/perception/rate_gate.hpp"
#include "ari_social_sim/perception/sound_map.hpp"
#include "conversions/hri_messages.hpp"
#include "conversions/perception_markers.hpp"
#include "conversions/world_state.hpp"
#include "input_counters.hpp"
#include "per_id_handle.hpp"
#include "ros_params.hpp"

namespace ari_social_sim::nodes {
namespace {

constexpr char kMapFrame[] = "map";
// In 2D mode no camera frames exist: ROS4HRI frames hang from ARI's base instead of the sensor.
constexpr char kRobotFrame[] = "base_footprint";
constexpr double kSoundMapResolution_m = 0.05;
constexpr char kMapTopic[] = "/map";
constexpr char kWorldStateTopic[] = "/sim/world_state";

struct BodyTopics {
  ros::Publisher roi;
};
struct FaceTopics {
  ros::Publisher roi, expression, softbiometrics, mask;
};
struct VoiceTopics {
  ros::Publisher is_speaking, speech;
};
// A person's topics live while the person is known (PersonConfig::forget_after).
struct PersonTopics {
  ros::Publisher anonymous, name, face_id, body_id, voice_id, engagement, location_confidence,
      proxemic_space;
  std::optional<std::string> sent_name, sent_space;
};

// hri_person_manager's names of the proxemic zones.
const char* space_name(perception::ProxemicSpace space) {
  switch (space) {
    case perception::ProxemicSpace::kPersonal:
      return "personal";
    case perception::ProxemicSpace::kSocial:
      return "social";
    case perception::ProxemicSpace::kPublic:
      return "public";
    case perception::ProxemicSpace::kUnknown:
      break;
  }
  return "unknown";
}

std_msgs::String string_msg(const std::string& text) {
  std_msgs::String msg;
  msg.data = text;
  return msg;
}

// Publishes `value` on a latched topic unless it was the last value sent.
void publish_on_change(ros::Publisher& publisher, std::optional<std::string>& sent,
                       const std::string& value) {
  if (sent != value) {
    publisher.publish(string_msg(value));
    sent = value;
  }
}

// The matchers' own random stream, apart from the pipeline's (PerceptionPipeline's streams 1-5).
constexpr uint64_t kMatcherStream = 6;

class HriPerceptionNode {
 public:
  HriPerceptionNode(const perception::PerceptionRunConfig& run,
                    const perception::PerceptionConfig& config,
                    std::optional<model::OccupancyGrid> sound_map)
      : run_(run),
        pipeline_(config),
        rate_gate_(run.max_rate_hz),
        matcher_(pipeline_.config().matchers,
                 core::Rng::for_stream(pipeline_.config().seed, kMatcherStream)),
        bodies_([this](const std::string& id) { return advertise_body(id); }),
        faces_([this](const std::string& id) { return advertise_face(id); }),
        voices_([this](const std::string& id) { return advertise_voice(id); }),
        persons_([this](const std::string& id) { return advertise_person(id); }) {
    if (sound_map) {
      pipeline_.set_sound_map(std::move(*sound_map));
    }
    faces_tracked_ = nh_.advertise<IdsList>("/humans/faces/tracked", 1);
    bodies_tracked_ = nh_.advertise<IdsList>("/humans/bodies/tracked", 1);
    voices_tracked_ = nh_.advertise<IdsList>("/humans/voices/tracked", 1);
    if (with_persons()) {
      persons_tracked_ = nh_.advertise<IdsList>("/humans/persons/tracked", 1, /*latch=*/true);
      persons_known_ = nh_.advertise<IdsList>("/humans/persons/known", 1, /*latch=*/true);
      for (const perception::ProxemicSpace space :
           {perception::ProxemicSpace::kPersonal, perception::ProxemicSpace::kSocial,
            perception::ProxemicSpace::kPublic}) {
        in_space_[space] = nh_.advertise<IdsList>(
            std::string("/humans/persons/in_") + space_name(space) + "_space", 1, true);
      }
    }
    matches_ = nh_.advertise<IdsMatch>("/humans/candidate_matches", 50);
    gazing_ = nh_.advertise<Gaze>("/humans/interactions/gazing", 50);
    markers_ = private_nh_.advertise<visualization_msgs::MarkerArray>("markers", 1);
    diagnostics_pub_ = nh_.advertise<diagnostic_msgs::DiagnosticArray>("/diagnostics", 10);
    map_sub_ = nh_.subscribe(kMapTopic, 1, &HriPerceptionNode::on_map, this);
    // No Nagle delay: each world state should be perceived as soon as it is published.
    state_sub_ = nh_.subscribe(kWorldStateTopic, 1, &HriPerceptionNode::on_world_state, this,
                               ros::TransportHints().tcpNoDelay());
  }

 private:
  // In detectors mode a person manager (hri_person_manager) makes the persons.
  bool with_persons() const { return run_.mode == perception::PerceptionRunConfig::Mode::kSim; }

  BodyTopics advertise_body(const std::string& id) {
    ros::NodeHandle nh = per_id_handle(nh_);
    const std::string ns = "/humans/bodies/" + id + "/";
    return {nh.advertise<NormalizedRegionOfInterest2D>(ns + "roi", 1)};
  }
  FaceTopics advertise_face(const std::string& id) {
    ros::NodeHandle nh = per_id_handle(nh_);
    const std::string ns = "/humans/faces/" + id + "/";
    return {nh.advertise<NormalizedRegionOfInterest2D>(ns + "roi", 1),
            nh.advertise<Expression>(ns + "expression", 1),
            nh.advertise<SoftBiometrics>(ns + "softbiometrics", 1),
            nh.advertise<std_msgs::Bool>(ns + "mask", 1)};
  }
  VoiceTopics advertise_voice(const std::string& id) {
    ros::NodeHandle nh = per_id_handle(nh_);
    const std::string ns = "/humans/voices/" + id + "/";
    return {nh.advertise<std_msgs::Bool>(ns + "is_speaking", 1),
            nh.advertise<LiveSpeech>(ns + "speech", 10)};
  }
  PersonTopics advertise_person(const std::string& id) {
    ros::NodeHandle nh = per_id_handle(nh_);
    const std::string ns = "/humans/persons/" + id + "/";
    PersonTopics topics;
    topics.anonymous = nh.advertise<std_msgs::Bool>(ns + "anonymous", 1, true);
    topics.name = nh.advertise<std_msgs::String>(ns + "name", 1, true);
    topics.face_id = nh.advertise<std_msgs::String>(ns + "face_id", 1, true);
    topics.body_id = nh.advertise<std_msgs::String>(ns + "body_id", 1, true);
    topics.voice_id = nh.advertise<std_msgs::String>(ns + "voice_id", 1, true);
    topics.engagement = nh.advertise<EngagementLevel>(ns + "engagement_status", 1);
    topics.location_confidence = nh.advertise<std_msgs::Float32>(ns + "location_confidence", 1);
    topics.proxemic_space = nh.advertise<std_msgs::String>(ns + "proxemic_space", 1, true);
    // Everyone is recognised from ARI's database of known persons (person_id_of).
    std_msgs::Bool anonymous;
    anonymous.data = false;
    topics.anonymous.publish(anonymous);
    return topics;
  }

  // Drops a message the perception could not use (counted on /diagnostics); true if it is fine.
  template <class Message>
  bool usable(const char* topic, const Message& msg) {
    const std::optional<InputProblem> problem = input_problem(msg);
    if (problem) {
      inputs_.drop(topic, problem->field, problem->what);
    }
    inputs_.publish_when_due(diagnostics_pub_, ros::Time::now());
    return !problem;
  }

  void on_map(const nav_msgs::OccupancyGrid::ConstPtr& msg) {
    if (!usable(kMapTopic, *msg)) {
      return;
    }
    pipeline_.set_sight_map(from_msg(*msg));
    has_map_ = true;
  }

  void on_world_state(const WorldState::ConstPtr& msg) {
    if (!usable(kWorldStateTopic, *msg)) {
      return;
    }
    if (!has_map_) {
      ROS_WARN_THROTTLE(5.0, "hri_perception_node: waiting for /map before perceiving");
      return;
    }
    if (!rate_gate_.take(msg->header.stamp.toSec())) {
      return;
    }
    const perception::PerceptionFrame& frame = pipeline_.update(from_msg(*msg));
    publish(frame, msg->header.stamp);
  }

  void publish(const perception::PerceptionFrame& frame, const ros::Time& stamp) {
    std_msgs::Header header;
    header.stamp = stamp;
    header.frame_id = kRobotFrame;
    const double now_s = frame.time_s;

    // Per-id subtopics first, so that a listener diffing the tracked lists below finds every
    // new id's topics already there.
    for (const perception::PerceivedBody& body : frame.bodies) {
      bodies_.of(body.body_id, now_s).roi.publish(roi_msg(body.roi, body.visible_fraction, header));
    }
    for (const perception::PerceivedFace& face : frame.faces) {
      FaceTopics& topics = faces_.of(face.face_id, now_s);
      topics.roi.publish(roi_msg(face.roi, 1.0, header));
      topics.expression.publish(expression_msg(face, header));
      topics.softbiometrics.publish(softbiometrics_msg(face, header));
      std_msgs::Bool mask;
      mask.data = face.mask;
      topics.mask.publish(mask);
    }
    const std::string& language = pipeline_.config().microphone.language;
    for (const perception::PerceivedVoice& voice : frame.voices) {
      VoiceTopics& topics = voices_.of(voice.voice_id, now_s);
      std_msgs::Bool speaking;
      speaking.data = voice.is_speaking;
      topics.is_speaking.publish(speaking);
      for (const perception::SpeechResult& result : voice.speech) {
        topics.speech.publish(speech_msg(result, language, header));
      }
    }
    if (with_persons()) {
      publish_persons(frame, header);
    }

    const bool sim = with_persons();
    const HriFrameMessages messages =
        hri_frame_messages(frame, sim ? perception::person_links(frame) : matcher_.update(frame),
                           sim, pipeline_.config().human_model, stamp, kRobotFrame, kMapFrame);
    for (const IdsMatch& match : messages.matches) {
      matches_.publish(match);
    }
    for (const Gaze& gaze : messages.gazes) {
      gazing_.publish(gaze);
    }
    if (!messages.transforms.empty()) {
      tf_.sendTransform(messages.transforms);
    }
    faces_tracked_.publish(messages.faces_tracked);
    bodies_tracked_.publish(messages.bodies_tracked);
    voices_tracked_.publish(messages.voices_tracked);
    if (sim) {
      persons_tracked_.publish(messages.persons_tracked);
      persons_known_.publish(messages.persons_known);
    }

    bodies_.retire(now_s, run_.id_linger_s);
    faces_.retire(now_s, run_.id_linger_s);
    voices_.retire(now_s, run_.id_linger_s);
    publish_markers(frame);
  }

  // The person manager's per-person topics. The links are sent on every frame, as
  // hri_person_manager does on every update: a client (pyhri) accepts a face or body link only if
  // that face or body is already tracked when the link arrives, and a link sent once would be
  // lost for good had it come first.
  void publish_persons(const perception::PerceptionFrame& frame, const std_msgs::Header& header) {
    std::map<perception::ProxemicSpace, std::vector<std::string>> in_space;
    for (const perception::PersonReport& person : frame.persons) {
      in_space[person.proxemic_space].push_back(person.person_id);
      PersonTopics& topics = persons_.of(person.person_id, frame.time_s);
      publish_on_change(topics.name, topics.sent_name, person.name);
      topics.face_id.publish(string_msg(person.face_id));
      topics.body_id.publish(string_msg(person.body_id));
      topics.voice_id.publish(string_msg(person.voice_id));
      topics.engagement.publish(engagement_msg(person.engagement, header));
      std_msgs::Float32 confidence;
      confidence.data = static_cast<float>(person.location_confidence);
      topics.location_confidence.publish(confidence);
      publish_on_change(topics.proxemic_space, topics.sent_space,
                        space_name(person.proxemic_space));
    }
    // A forgotten person is no longer in the frame: its topics are shut down.
    persons_.retire(frame.time_s, 0.0);
    // Latched, sent when they change, as hri_person_manager does.
    for (auto& [space, publisher] : in_space_) {
      const std::vector<std::string>& ids = in_space[space];
      if (ids != sent_in_space_[space]) {
        publisher.publish(ids_msg(ids, header));
        sent_in_space_[space] = ids;
      }
    }
  }

  void publish_markers(const perception::PerceptionFrame& frame) {
    const ros::WallTime now = ros::WallTime::now();
    if (markers_.getNumSubscribers() == 0 ||
        (now - last_markers_).toSec() < 1.0 / run_.marker_rate_hz) {
      return;
    }
    last_markers_ = now;
    markers_.publish(perception_markers(frame, pipeline_.config(), kMapFrame));
  }

  perception::PerceptionRunConfig run_;
  perception::PerceptionPipeline pipeline_;
  perception::RateGate rate_gate_;
  perception::CandidateMatcher matcher_;  ///< Detectors mode only.
  bool has_map_{false};
  ros::WallTime last_markers_;

  ros::NodeHandle nh_;
  ros::NodeHandle private_nh_{"~"};
  InputCounters inputs_{"hri_perception_node"};
  ros::Publisher diagnostics_pub_;
  ros::Publisher faces_tracked_, bodies_tracked_, voices_tracked_, persons_tracked_, persons_known_,
      matches_, gazing_, markers_;
  ros::Subscriber map_sub_, state_sub_;
  tf2_ros::TransformBroadcaster tf_;
  // Per-id topics, advertised when an id appears and shut down (by dropping the publishers)
  // once it has been absent for ~id_linger; persons' once forgotten.
  perception::PerIdStore<BodyTopics> bodies_;
  perception::PerIdStore<FaceTopics> faces_;
  perception::PerIdStore<VoiceTopics> voices_;
  perception::PerIdStore<PersonTopics> persons_;
  std::map<perception::ProxemicSpace, ros::Publisher> in_space_;
  std::map<perception::ProxemicSpace, std::vector<std::string>> sent_in_space_;
};

}  // namespace
}  // namespace ari_social_sim::nodes

int main(int argc, char** argv) {
  using namespace ari_social_sim;
  ros::init(argc, argv, "hri_perception");
  ros::NodeHandle private_handle("~");
  perception::PerceptionRunConfig run;
  perception::PerceptionConfig config;
  std::optional<model::OccupancyGrid> sound_map;
  try {
    run = perception::PerceptionRunConfig::from_yaml(nodes::read_private_params(private_handle));
    if (run.config.empty()) {
      run.config = ros::package::getPath("ari_social_sim") + "/config/perception.yaml";
    }
    config = perception::PerceptionConfig::load_file(run.config);
    if (run.seed >= 0) {
      config.seed = static_cast<unsigned>(run.seed);
    }
    if (run.errors_enabled) {
      config.errors_enabled = *run.errors_enabled;
    }
    if (run.person_ids) {
      config.persons.id_style = *run.person_ids;
    }
    if (!run.world.empty()) {
      sound_map = perception::rasterize_walls(model::load_world_file(run.world),
                                              nodes::kSoundMapResolution_m);
    }
  } catch (const core::Error& e) {
    ROS_FATAL("%s", e.what());
    return 2;
  }
  const bool detectors = run.mode == perception::PerceptionRunConfig::Mode::kDetectors;
  ROS_INFO("hri_perception_node: %s mode, %s, seed %u, error models %s, sound blocked by %s",
           detectors ? "detectors" : "sim", run.config.c_str(), config.seed,
           config.errors_enabled ? "on" : "off",
           run.world.empty() ? "/map" : ("the walls of " + run.world).c_str());
  nodes::HriPerceptionNode node(run, config, std::move(sound_map));
  ros::spin();
  return 0;
}
