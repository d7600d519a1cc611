// speech_recognition_node: ARI's speech recognition on the microphone array, as a ROS4HRI voice
// node (docs/audio.md, "Speech recognition"): pocketsphinx on /audio/channel0, each utterance
// given to the voice of the direction it came from (/audio/sound_direction), published as
// /humans/voices/<id>/speech (incremental and final, with confidence) and is_speaking, with
// /humans/voices/tracked and a voice_<id> frame. Reads parameters, builds the language model and
// converts at the edges; the recogniser and the voice tracks are the audio core's.

#include <geometry_msgs/TransformStamped.h>
#include <ros/package.h>
#include <ros/ros.h>
#include <std_msgs/Bool.h>
#include <std_msgs/Int32.h>
#include <tf2_ros/transform_broadcaster.h>

#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ari_social_sim/AudioData.h"
#include "ari_social_sim/IdsList.h"
#include "ari_social_sim/LiveSpeech.h"
#include "ari_social_sim/audio/domain_grammar.hpp"
#include "ari_social_sim/audio/speech_recognition_run_config.hpp"
#include "ari_social_sim/audio/speech_recognizer.hpp"
#include "ari_social_sim/audio/voice_tracks.hpp"
#include "ari_social_sim/scenario/heard_lines.hpp"
#include "ari_social_sim/scenario/scenario.hpp"
#include "node_support/node_main.hpp"
#include "node_support/per_id_handle.hpp"
#include "node_support/ros_params.hpp"

namespace ari_social_sim::nodes {
namespace {

constexpr const char* kArrayFrame = "torso_mic_front_link";
constexpr const char* kLanguage = "en-US";

std::string package_file(const std::string& given, const std::string& relative) {
  return given.empty() ? ros::package::getPath("ari_social_sim") + "/" + relative : given;
}

// The recogniser's settings: the general model, or a trigram model of the domain's sentences and
// the scenario's human lines, each of these counted scenario_line_weight times.
audio::RecognizerSettings recognizer_settings(const audio::SpeechRecognitionRunConfig& run) {
  audio::RecognizerSettings settings;
  if (run.language_model == audio::SpeechRecognitionRunConfig::LanguageModel::kGeneral) {
    return settings;
  }
  std::vector<std::string> sentences = audio::read_domain_sentences(
      package_file(run.templates, "config/dialogue/nlg_templates.yaml"),
      package_file(run.domain, "config/dialogue/hospital_domain.yaml"));
  if (!run.scenario.empty()) {
    for (const std::string& line :
         scenario::HeardLines(scenario::load_scenario_file(run.scenario).script).texts()) {
      sentences.insert(sentences.end(), run.scenario_line_weight, audio::recognizer_words(line));
    }
  }
  size_t left_out = 0;
  settings.language_model_arpa =
      audio::language_model_for(sentences, settings.model_dir, &left_out);
  ROS_INFO(
      "speech_recognition_node: language model of %zu sentences (%zu with a word pocketsphinx "
      "cannot pronounce left out)",
      sentences.size() - left_out, left_out);
  return settings;
}

class SpeechRecognitionNode {
 public:
  explicit SpeechRecognitionNode(const audio::SpeechRecognitionRunConfig& run)
      : run_(run),
        recognizer_(recognizer_settings(run)),
        tracks_(run.voice_separation_deg * M_PI / 180.0) {
    tracked_ = nh_.advertise<IdsList>("/humans/voices/tracked", 1, /*latch=*/true);
    direction_sub_ =
        nh_.subscribe("/audio/sound_direction", 10, &SpeechRecognitionNode::on_direction, this);
    audio_sub_ = nh_.subscribe("/audio/channel0", 100, &SpeechRecognitionNode::on_audio, this);
  }

 private:
  struct VoiceTopics {
    ros::Publisher speech, is_speaking;
  };

  void on_direction(const std_msgs::Int32& msg) {
    direction_rad_ = msg.data * M_PI / 180.0;
    if (speaking_) {
      place_voice(*speaking_);
    }
  }

  void on_audio(const AudioData& msg) {
    std::vector<int16_t> samples(msg.data.size() / 2);
    for (size_t i = 0; i < samples.size(); ++i) {
      samples[i] = static_cast<int16_t>(msg.data[2 * i] | (msg.data[2 * i + 1] << 8));
    }
    for (const audio::Recognition& recognition :
         recognizer_.process(samples.data(), samples.size())) {
      publish(recognition);
    }
  }

  void publish(const audio::Recognition& recognition) {
    if (!speaking_) {
      speaking_ = tracks_.voice_from(direction_rad_);
      publish_speaking(*speaking_, true);
      place_voice(*speaking_);
    }
    LiveSpeech speech;
    speech.header.stamp = ros::Time::now();
    speech.language = kLanguage;
    if (recognition.final) {
      speech.final = recognition.text;
      speech.confidence = recognition.confidence;
    } else {
      speech.incremental = recognition.text;
    }
    voice(*speaking_).speech.publish(speech);
    if (recognition.final) {
      ROS_INFO("speech_recognition_node: %s said \"%s\" (confidence %.2f)", speaking_->c_str(),
               recognition.text.c_str(), recognition.confidence);
      publish_speaking(*speaking_, false);
      speaking_.reset();
    }
  }

  // The topics of voice `id`, advertised (and /humans/voices/tracked updated) when first heard.
  VoiceTopics& voice(const std::string& id) {
    auto found = voices_.find(id);
    if (found == voices_.end()) {
      ros::NodeHandle handle = per_id_handle(nh_);
      const std::string ns = "/humans/voices/" + id + "/";
      found = voices_
                  .emplace(id, VoiceTopics{handle.advertise<LiveSpeech>(ns + "speech", 10),
                                           handle.advertise<std_msgs::Bool>(ns + "is_speaking", 1,
                                                                            /*latch=*/true)})
                  .first;
      IdsList tracked;
      tracked.header.stamp = ros::Time::now();
      tracked.ids = tracks_.ids();
      tracked_.publish(tracked);
    }
    return found->second;
  }

  void publish_speaking(const std::string& id, bool speaking) {
    std_msgs::Bool msg;
    msg.data = speaking;
    voice(id).is_speaking.publish(msg);
  }

  // voice_<id> at voice_range along the direction the voice was last heard from. At most once
  // per stamp: audio arrives in bursts between two clock ticks, and tf refuses (and every
  // listener warns about) a second transform of a frame at the same time.
  void place_voice(const std::string& id) {
    const ros::Time now = ros::Time::now();
    ros::Time& placed = placed_at_[id];
    if (placed == now) {
      return;
    }
    placed = now;
    geometry_msgs::TransformStamped t;
    t.header.stamp = now;
    t.header.frame_id = kArrayFrame;
    t.child_frame_id = "voice_" + id;
    t.transform.translation.x = run_.voice_range_m * std::cos(direction_rad_);
    t.transform.translation.y = run_.voice_range_m * std::sin(direction_rad_);
    t.transform.rotation.w = 1.0;
    broadcaster_.sendTransform(t);
  }

  ros::NodeHandle nh_;
  audio::SpeechRecognitionRunConfig run_;
  audio::SpeechRecognizer recognizer_;
  audio::VoiceTracks tracks_;
  double direction_rad_{0.0};            // the latest direction of arrival; ahead until one comes
  std::optional<std::string> speaking_;  // the voice of the utterance going on
  std::map<std::string, VoiceTopics> voices_;
  tf2_ros::TransformBroadcaster broadcaster_;
  std::map<std::string, ros::Time> placed_at_;  // the stamp of each voice frame last sent
  ros::Publisher tracked_;
  ros::Subscriber direction_sub_, audio_sub_;
};

}  // namespace
}  // namespace ari_social_sim::nodes

int main(int argc, char** argv) {
  using namespace ari_social_sim;
  return nodes::run_node(argc, argv, "speech_recognition_node", [] {
    ros::NodeHandle private_handle("~");
    const audio::SpeechRecognitionRunConfig run =
        audio::SpeechRecognitionRunConfig::from_yaml(nodes::read_private_params(private_handle));
    nodes::SpeechRecognitionNode node(run);
    ros::spin();
    return 0;
  });
}
