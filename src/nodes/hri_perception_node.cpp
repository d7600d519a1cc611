// hri_perception_node: what ARI's ROS4HRI perception stack would publish about the people around
// it, computed from the world's ground truth (/sim/world_state, /map) by the perception core.
// Reads parameters, builds the core, wires topics and tf, converts at the edges.

#include <diagnostic_msgs/DiagnosticArray.h>
#include <nav_msgs/OccupancyGrid.h>
#include <ros/package.h>
#include <ros/ros.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <std_msgs/Bool.h>
#include <std_msgs/Float32.h>
#include <std_msgs/String.h>
#include <tf2_ros/transform_broadcaster.h>
#include <visualization_msgs/MarkerArray.h>

#include <Eigen/Geometry>
#include <map>
#include <memory>
#include <optional>

#include "ari_social_sim/WorldState.h"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/rng_streams.hpp"
#include "ari_social_sim/model/world_file.hpp"
#include "ari_social_sim/perception/candidate_matches.hpp"
#include "ari_social_sim/perception/per_id_store.hpp"
#include "ari_social_sim/perception/perception_pipeline.hpp"
#include "ari_social_sim/perception/perception_run_config.hpp"
#include "ari_social_sim/perception/rate_gate.hpp"
#include "ari_social_sim/perception/sound_map.hpp"
#include "ari_social_sim/rendering/drawn_people.hpp"
#include "ari_social_sim/rendering/people_crops.hpp"
#include "node_support/image.hpp"
#include "node_support/input_counters.hpp"
#include "node_support/node_main.hpp"
#include "node_support/per_id_handle.hpp"
#include "node_support/renewing_tf_buffer.hpp"
#include "node_support/ros_params.hpp"
#include "node_support/single_publisher.hpp"
#include "perception_conversions/hri_messages.hpp"
#include "perception_conversions/perception_markers.hpp"
#include "world_conversions/transform.hpp"
#include "world_conversions/world_state.hpp"

namespace ari_social_sim::nodes {
namespace {

constexpr char kMapFrame[] = "map";
// In 2D mode no camera frames exist: ROS4HRI frames hang from ARI's base instead of the sensor.
constexpr char kRobotFrame[] = "base_footprint";
constexpr double kSoundMapResolution_m = 0.05;
constexpr char kMapTopic[] = "/map";
constexpr char kWorldStateTopic[] = "/sim/world_state";
// With ~crops: ARI's head camera, which ari_physics_node renders while someone listens.
constexpr char kHeadImageTopic[] = "/head_front_camera/color/image_raw";
constexpr char kHeadInfoTopic[] = "/head_front_camera/color/camera_info";
// hri_face_detect's default side of the cropped and aligned face images (/humans/faces/width
// and /humans/faces/height).
constexpr int kDefaultFaceSize = 128;

struct BodyTopics {
  ros::Publisher roi, posture, cropped;  // cropped with ~crops only
};
struct FaceTopics {
  ros::Publisher roi, expression, softbiometrics, mask, cropped, aligned;  // the last two: ~crops
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

class HriPerceptionNode {
 public:
  HriPerceptionNode(const perception::PerceptionRunConfig& run,
                    const perception::PerceptionConfig& config,
                    std::optional<model::OccupancyGrid> sound_map)
      : run_(run),
        pipeline_(config),
        rate_gate_(run.max_rate_hz),
        matcher_(pipeline_.config().matchers,
                 core::rng_for(pipeline_.config().seed, core::rng_streams::kPerceptionMatcher)),
        bodies_([this](const std::string& id) { return advertise_body(id); }),
        faces_([this](const std::string& id) { return advertise_face(id); }),
        voices_([this](const std::string& id) { return advertise_voice(id); }),
        persons_([this](const std::string& id) { return advertise_person(id); }) {
    if (sound_map) {
      pipeline_.set_sound_map(std::move(*sound_map));
    }
    faces_tracked_ = nh_.advertise<IdsList>("/humans/faces/tracked", 1);
    bodies_tracked_ = nh_.advertise<IdsList>("/humans/bodies/tracked", 1);
    if (run_.voices) {
      voices_tracked_ = nh_.advertise<IdsList>("/humans/voices/tracked", 1);
    } else {
      pipeline_.stop_listening();  // the voices are another node's (speech:=audio)
    }
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
    if (run_.crops) {
      start_crops();
    }
  }

 private:
  // In detectors mode a person manager (hri_person_manager) makes the persons.
  bool with_persons() const { return run_.mode == perception::PerceptionRunConfig::Mode::kSim; }

  BodyTopics advertise_body(const std::string& id) {
    ros::NodeHandle nh = per_id_handle(nh_);
    const std::string ns = "/humans/bodies/" + id + "/";
    BodyTopics topics{nh.advertise<NormalizedRegionOfInterest2D>(ns + "roi", 1),
                      nh.advertise<BodyPosture>(ns + "posture", 1),
                      {}};
    if (run_.crops) {
      topics.cropped = nh.advertise<sensor_msgs::Image>(ns + "cropped", 1);
    }
    return topics;
  }
  FaceTopics advertise_face(const std::string& id) {
    ros::NodeHandle nh = per_id_handle(nh_);
    const std::string ns = "/humans/faces/" + id + "/";
    FaceTopics topics{nh.advertise<NormalizedRegionOfInterest2D>(ns + "roi", 1),
                      nh.advertise<Expression>(ns + "expression", 1),
                      nh.advertise<SoftBiometrics>(ns + "softbiometrics", 1),
                      nh.advertise<std_msgs::Bool>(ns + "mask", 1),
                      {},
                      {}};
    if (run_.crops) {
      topics.cropped = nh.advertise<sensor_msgs::Image>(ns + "cropped", 1);
      topics.aligned = nh.advertise<sensor_msgs::Image>(ns + "aligned", 1);
    }
    return topics;
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

  void on_map(const ros::MessageEvent<const nav_msgs::OccupancyGrid>& event) {
    const nav_msgs::OccupancyGrid::ConstPtr& msg = event.getConstMessage();
    if (!map_publisher_.accept(event.getPublisherName()) || !usable(kMapTopic, *msg)) {
      return;
    }
    pipeline_.set_sight_map(from_msg(*msg));
    has_map_ = true;
  }

  void on_world_state(const ros::MessageEvent<const WorldState>& event) {
    const WorldState::ConstPtr& msg = event.getConstMessage();
    clock_publishers_.check_when_due();
    if (!state_publisher_.accept(event.getPublisherName()) || !usable(kWorldStateTopic, *msg)) {
      return;
    }
    if (!has_map_) {
      ROS_WARN_THROTTLE(5.0, "hri_perception_node: waiting for /map before perceiving");
      return;
    }
    const bool perceived = rate_gate_.take(msg->header.stamp.toSec());
    if (!perceived && !run_.crops) {
      return;
    }
    const world::WorldSnapshot snapshot = from_msg(*msg);
    if (run_.crops) {
      // Every state, perceived or not: the head camera draws each one.
      drawn_->add_state(msg->header.stamp.toSec(), snapshot.humans);
    }
    if (!perceived) {
      cut_pending_image();  // ~crops only
      return;
    }
    const perception::PerceptionFrame& frame = pipeline_.update(snapshot);
    publish(frame, msg->header.stamp);
    if (run_.crops) {
      tracked_faces_.clear();
      tracked_bodies_.clear();
      for (const perception::PerceivedFace& face : frame.faces) {
        tracked_faces_.push_back({face.face_id, face.human, face.roi});
      }
      for (const perception::PerceivedBody& body : frame.bodies) {
        tracked_bodies_.push_back({body.body_id, body.human, body.roi});
      }
      tracked_time_s_ = frame.time_s;
      cut_pending_image();
    }
  }

  // ~crops: the face and body images cut from the head camera, where the people ari_physics_node
  // drew are. Their figures are rebuilt here from the same inputs (the world state's people, the
  // same appearance seed), so the boxes are those of the drawn figures, projected.
  void start_crops() {
    uint64_t seed = 1;
    if (run_.appearance_seed) {
      seed = *run_.appearance_seed;
    } else {
      int physics_seed = 1;
      if (nh_.getParam("/ari_physics_node/appearance_seed", physics_seed) && physics_seed >= 0) {
        seed = static_cast<uint64_t>(physics_seed);
      }
    }
    drawn_.emplace(seed);
    int width = kDefaultFaceSize, height = kDefaultFaceSize;
    nh_.param("/humans/faces/width", width, kDefaultFaceSize);
    nh_.param("/humans/faces/height", height, kDefaultFaceSize);
    if (width != height || width <= 0) {
      ROS_ERROR(
          "hri_perception_node: /humans/faces/width and /humans/faces/height must be equal "
          "and positive; face images are %d px square",
          width > 0 ? width : kDefaultFaceSize);
    }
    face_size_ = width > 0 ? width : kDefaultFaceSize;
    tf_buffer_ = std::make_unique<RenewingTfBuffer>();
    info_sub_ = nh_.subscribe(kHeadInfoTopic, 1, &HriPerceptionNode::on_camera_info, this);
    image_sub_ = nh_.subscribe(kHeadImageTopic, 1, &HriPerceptionNode::on_image, this);
    ROS_INFO("hri_perception_node: face and body crops from %s, appearance seed %lu, faces %d px",
             kHeadImageTopic, static_cast<unsigned long>(seed), face_size_);
  }

  void on_camera_info(const sensor_msgs::CameraInfo::ConstPtr& msg) {
    const std::optional<rendering::PinholeModel> model = pinhole_of(*msg);
    if (!model) {
      ROS_WARN_THROTTLE(5.0, "hri_perception_node: %s: no usable intrinsics", kHeadInfoTopic);
      return;
    }
    head_camera_ = model;
  }

  // Where the camera was at `header`'s stamp; or, when the stamp is not in the buffer, the latest
  // pose if no more than `latest_within_s` away from it (0: the stamp's pose only).
  std::optional<Eigen::Isometry3d> camera_pose(const std_msgs::Header& header,
                                               double latest_within_s) {
    tf_buffer_->renew_if_stale();
    inputs_.add_drops("tf", "absurd transform", tf_buffer_->take_refused().count);
    const tf2_ros::Buffer& buffer = tf_buffer_->buffer();
    try {
      return isometry_of(
          buffer.lookupTransform(kMapFrame, header.frame_id, header.stamp).transform);
    } catch (const tf2::TransformException&) {
      if (latest_within_s <= 0.0) {
        return std::nullopt;
      }
    }
    geometry_msgs::TransformStamped latest;
    try {
      latest = buffer.lookupTransform(kMapFrame, header.frame_id, ros::Time(0));
    } catch (const tf2::TransformException& e) {
      ROS_WARN_THROTTLE(5.0, "hri_perception_node: no head camera pose (crops, face roi): %s",
                        e.what());
      return std::nullopt;
    }
    const double offset_s = (latest.header.stamp - header.stamp).toSec();
    if (std::abs(offset_s) > latest_within_s) {
      ROS_WARN_THROTTLE(5.0,
                        "hri_perception_node: no head camera pose (crops, face roi): the latest "
                        "%s in %s is %.2f s off",
                        header.frame_id.c_str(), kMapFrame, offset_s);
      return std::nullopt;
    }
    return isometry_of(latest.transform);
  }

  static sensor_msgs::Image image_msg(const cv::Mat& bgr, const std_msgs::Header& header) {
    sensor_msgs::Image msg = to_image_msg(bgr, "bgr8");
    msg.header = header;
    return msg;
  }

  // An image waits for the camera's pose at its stamp (robot_state_publisher sends the head's
  // transforms a little after the physics renders) and for the world state it was drawn from
  // (on a busy machine it can come after the image): it is cut when both have come, on the next
  // world state or image, or with the latest pose and state once it has waited kMaxImageWait_s.
  void on_image(const sensor_msgs::Image::ConstPtr& msg) {
    pending_image_ = msg;  // one waiting at a time: a newer image replaces it
    cut_pending_image();
  }

  void cut_pending_image() {
    if (!pending_image_) {
      return;
    }
    const sensor_msgs::Image::ConstPtr msg = pending_image_;
    const bool waited = (ros::Time::now() - msg->header.stamp).toSec() > kMaxImageWait_s;
    std::optional<Eigen::Isometry3d> X_map_optical;
    if (tf_buffer_) {
      X_map_optical = camera_pose(msg->header, waited ? kMaxPoseAge_s : 0.0);
    }
    if ((!X_map_optical || !drawn_->has_state_for(msg->header.stamp.toSec())) && !waited) {
      return;  // again later
    }
    pending_image_.reset();
    if (X_map_optical) {
      cut(*msg, *X_map_optical);
    }
  }

  // Whether anyone listens to `publisher` (advertised with ~crops only).
  static bool wanted(const ros::Publisher& publisher) {
    return publisher && publisher.getNumSubscribers() > 0;
  }

  // Whether anyone listens to a crop of the last perceived frame's faces and bodies.
  bool crops_wanted() {
    for (const TrackedPart& face : tracked_faces_) {
      FaceTopics& topics = faces_.of(face.id, tracked_time_s_);
      if (wanted(topics.cropped) || wanted(topics.aligned)) {
        return true;
      }
    }
    for (const TrackedPart& body : tracked_bodies_) {
      if (wanted(bodies_.of(body.id, tracked_time_s_).cropped)) {
        return true;
      }
    }
    return false;
  }

  // The faces' roi and the crops of one image, the camera at X_map_optical, for the last perceived
  // frame's faces and bodies.
  void cut(const sensor_msgs::Image& msg, const Eigen::Isometry3d& X_map_optical) {
    if (!head_camera_ || drawn_->empty() || tracked_time_s_ < 0.0 ||
        (tracked_faces_.empty() && tracked_bodies_.empty())) {
      return;
    }
    if (static_cast<int>(msg.width) != head_camera_->width ||
        static_cast<int>(msg.height) != head_camera_->height) {
      ROS_WARN_THROTTLE(5.0, "hri_perception_node: %s is %ux%u, its camera_info says %dx%d",
                        kHeadImageTopic, msg.width, msg.height, head_camera_->width,
                        head_camera_->height);
      return;
    }
    const std::vector<rendering::PosedPerson>& posed_people =
        drawn_->pose_at(msg.header.stamp.toSec());
    publish_face_rois(posed_people, X_map_optical, msg.header);
    if (!crops_wanted()) {
      return;  // no-one listens: no conversion
    }
    const cv::Mat image = bgr_of(msg);
    if (image.empty()) {
      ROS_WARN_THROTTLE(5.0, "hri_perception_node: %s: encoding %s not handled (rgb8, bgr8)",
                        kHeadImageTopic, msg.encoding.c_str());
      return;
    }
    std::map<model::ObjectId, const rendering::PosedPerson*> posed;
    for (const rendering::PosedPerson& person : posed_people) {
      posed[static_cast<model::ObjectId>(person.id)] = &person;
    }
    const rendering::CameraView view{image, *head_camera_, X_map_optical};
    for (const TrackedPart& face : tracked_faces_) {
      const auto found = posed.find(face.human);
      if (found == posed.end()) {
        continue;
      }
      FaceTopics& topics = faces_.of(face.id, tracked_time_s_);
      const std::optional<rendering::FaceImages> images = rendering::face_images(
          *found->second, view, face_size_, {wanted(topics.cropped), wanted(topics.aligned)});
      if (images && !images->cropped.empty()) {
        topics.cropped.publish(image_msg(images->cropped, msg.header));
      }
      if (images && !images->aligned.empty()) {
        topics.aligned.publish(image_msg(images->aligned, msg.header));
      }
    }
    for (const TrackedPart& body : tracked_bodies_) {
      const auto found = posed.find(body.human);
      BodyTopics& topics = bodies_.of(body.id, tracked_time_s_);
      if (found == posed.end() || !wanted(topics.cropped)) {
        continue;
      }
      if (const std::optional<cv::Mat> body = rendering::body_image(*found->second, view)) {
        topics.cropped.publish(image_msg(*body, msg.header));
      }
    }
  }
  // ~crops: each face's roi as the head image shows it, with the image's header, as a detector
  // publishes it with its crops (the model's box where the image has no face of theirs).
  void publish_face_rois(const std::vector<rendering::PosedPerson>& posed,
                         const Eigen::Isometry3d& X_map_optical, const std_msgs::Header& header) {
    const rendering::PinholeModel& camera = *head_camera_;
    const std::map<uint32_t, rendering::PixelBox> boxes =
        rendering::face_boxes(posed, camera, X_map_optical);
    for (const TrackedPart& face : tracked_faces_) {
      perception::ImageRegion roi = face.roi;
      if (const auto box = boxes.find(static_cast<uint32_t>(face.human)); box != boxes.end()) {
        roi.xmin = double(box->second.x) / camera.width;
        roi.ymin = double(box->second.y) / camera.height;
        roi.xmax = double(box->second.x + box->second.width) / camera.width;
        roi.ymax = double(box->second.y + box->second.height) / camera.height;
      }
      faces_.of(face.id, tracked_time_s_).roi.publish(roi_msg(roi, 1.0, header));
    }
  }

  void publish(const perception::PerceptionFrame& frame, const ros::Time& stamp) {
    std_msgs::Header header;
    header.stamp = stamp;
    header.frame_id = kRobotFrame;
    const double now_s = frame.time_s;

    // Per-id subtopics first, so that a listener diffing the tracked lists below finds every
    // new id's topics already there.
    for (const perception::PerceivedBody& body : frame.bodies) {
      BodyTopics& topics = bodies_.of(body.body_id, now_s);
      topics.roi.publish(roi_msg(body.roi, body.visible_fraction, header));
      topics.posture.publish(posture_msg(body, header));
    }
    for (const perception::PerceivedFace& face : frame.faces) {
      FaceTopics& topics = faces_.of(face.face_id, now_s);
      // ~crops: the roi comes with the head image's crops, once that camera is known.
      if (!run_.crops || !head_camera_) {
        topics.roi.publish(roi_msg(face.roi, 1.0, header));
      }
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
    if (run_.voices) {
      voices_tracked_.publish(messages.voices_tracked);
    }
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
  // world_node's alone: a second world_node's map and world are refused.
  SinglePublisher map_publisher_{kMapTopic, &inputs_};
  SinglePublisher state_publisher_{kWorldStateTopic, &inputs_};
  PublisherCountWatch clock_publishers_{"/clock"};
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

  // ~crops
  // How far from an image's stamp the camera's pose may be, once it has waited for its own (the
  // head's transforms come ~0.1 s late).
  static constexpr double kMaxPoseAge_s = 0.1;
  static constexpr double kMaxImageWait_s = 0.5;
  sensor_msgs::Image::ConstPtr pending_image_;
  std::optional<rendering::DrawnPeople> drawn_;
  // The last perceived frame's faces and bodies: their id, the human each belongs to and the
  // model's roi.
  struct TrackedPart {
    std::string id;
    model::ObjectId human;
    perception::ImageRegion roi;
  };
  std::vector<TrackedPart> tracked_faces_, tracked_bodies_;
  double tracked_time_s_{-1.0};
  int face_size_{kDefaultFaceSize};
  std::optional<rendering::PinholeModel> head_camera_;
  std::unique_ptr<RenewingTfBuffer> tf_buffer_;
  ros::Subscriber image_sub_, info_sub_;
};

}  // namespace
}  // namespace ari_social_sim::nodes

int main(int argc, char** argv) {
  using namespace ari_social_sim;
  return nodes::run_node(argc, argv, "hri_perception", [] {
    ros::NodeHandle private_handle("~");
    perception::PerceptionRunConfig run =
        perception::PerceptionRunConfig::from_yaml(nodes::read_private_params(private_handle));
    if (run.config.empty()) {
      run.config = ros::package::getPath("ari_social_sim") + "/config/perception.yaml";
    }
    perception::PerceptionConfig config = perception::PerceptionConfig::load_file(run.config);
    config.seed = run.seed.value_or(config.seed);
    if (run.errors_enabled) {
      config.errors_enabled = *run.errors_enabled;
    }
    if (run.person_ids) {
      config.persons.id_style = *run.person_ids;
    }
    std::optional<model::OccupancyGrid> sound_map;
    if (!run.world.empty()) {
      sound_map = perception::rasterize_walls(model::load_world_file(run.world),
                                              nodes::kSoundMapResolution_m);
    }
    const bool detectors = run.mode == perception::PerceptionRunConfig::Mode::kDetectors;
    ROS_INFO("hri_perception_node: %s mode, %s, seed %lu, error models %s, sound blocked by %s",
             detectors ? "detectors" : "sim", run.config.c_str(),
             static_cast<unsigned long>(config.seed), config.errors_enabled ? "on" : "off",
             run.world.empty() ? "/map" : ("the walls of " + run.world).c_str());
    nodes::HriPerceptionNode node(run, config, std::move(sound_map));
    ros::spin();
    return 0;
  });
}
