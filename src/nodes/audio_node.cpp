// audio_node: ARI's microphone array in simulation, with the topics ARI's audio driver publishes
// (docs/audio.md): the array's six channels in 1024-sample chunks, the processed channel again
// as /audio/raw, voice activity and the direction of arrival. Reads parameters, builds the audio
// core (WorldAudio) from the scene, follows /sim/world_state and converts at the edges.

#include <geometry_msgs/PoseStamped.h>
#include <ros/package.h>
#include <ros/ros.h>
#include <std_msgs/Bool.h>
#include <std_msgs/Int32.h>

#include <array>
#include <cmath>
#include <memory>
#include <optional>
#include <string>

#include "ari_social_sim/AudioData.h"
#include "ari_social_sim/WorldState.h"
#include "ari_social_sim/audio/audio_run_config.hpp"
#include "ari_social_sim/audio/chunk_analysis.hpp"
#include "ari_social_sim/audio/sound_localizer.hpp"
#include "ari_social_sim/audio/world_audio.hpp"
#include "ari_social_sim/world/scene.hpp"
#include "node_support/node_main.hpp"
#include "node_support/ros_params.hpp"
#include "world_conversions/world_state.hpp"

namespace ari_social_sim::nodes {
namespace {

constexpr const char* kArrayFrame = "torso_mic_front_link";
// Chunks come in bursts when this node catches up with the world (after a lag, or when a paused
// world is stepped many steps at once); a queue of 10, as the real driver's, would drop all but
// the last ten of a burst. This holds a minute of audio per subscriber.
constexpr uint32_t kChunkQueue = 1000;

AudioData audio_msg(const std::vector<int16_t>& samples) {
  AudioData msg;
  msg.data.resize(samples.size() * 2);
  for (size_t i = 0; i < samples.size(); ++i) {
    const uint16_t bits = static_cast<uint16_t>(samples[i]);
    msg.data[2 * i] = static_cast<uint8_t>(bits & 0xff);  // little-endian, as ALSA's S16_LE
    msg.data[2 * i + 1] = static_cast<uint8_t>(bits >> 8);
  }
  return msg;
}

class AudioNode {
 public:
  AudioNode(const audio::AudioRunConfig& run, const world::Scene& scene)
      : run_(run), walls_(audio::walls_of(scene.world)), seed_(run.seed.value_or(scene.seed)) {
    for (size_t c = 0; c < channels_.size(); ++c) {
      channels_[c] = nh_.advertise<AudioData>("/audio/channel" + std::to_string(c), kChunkQueue);
    }
    raw_ = nh_.advertise<AudioData>("/audio/raw", kChunkQueue);
    voice_ = nh_.advertise<std_msgs::Bool>("/audio/voice_detected", 1, /*latch=*/true);
    direction_ = nh_.advertise<std_msgs::Int32>("/audio/sound_direction", 1, /*latch=*/true);
    localization_ =
        nh_.advertise<geometry_msgs::PoseStamped>("/audio/sound_localization", 1, /*latch=*/true);
    restart();
    world_state_ = nh_.subscribe("/sim/world_state", 100, &AudioNode::on_world_state, this);
  }

 private:
  void restart() {
    audio_ = std::make_unique<audio::WorldAudio>(run_.room, walls_, seed_, synthesizer_);
    last_time_s_.reset();
  }

  void on_world_state(const WorldState::ConstPtr& msg) {
    const world::WorldSnapshot snapshot = from_msg(*msg);
    if (last_time_s_ && snapshot.time_s < *last_time_s_) {
      restart();  // the world was reset: its time starts again
    }
    last_time_s_ = snapshot.time_s;
    audio_->observe(snapshot);
    for (const audio::ArrayChunk& chunk : audio_->chunks_until(snapshot.time_s)) {
      publish(chunk);
    }
  }

  void publish(const audio::ArrayChunk& chunk) {
    for (size_t c = 0; c < channels_.size(); ++c) {
      channels_[c].publish(audio_msg(chunk.channels[c]));
    }
    raw_.publish(audio_msg(chunk.channels[0]));
    const bool voice = audio::voice_in(chunk, run_.room);
    if (!voice_published_ || *voice_published_ != voice) {
      std_msgs::Bool msg;
      msg.data = voice;
      voice_.publish(msg);
      voice_published_ = voice;
    }
    if (voice) {
      publish_direction(chunk);
    }
  }

  // The direction of the chunk's loudest source, in the array's frame, as respeaker_ros gives it:
  // whole degrees on /audio/sound_direction and a pose whose yaw points at it.
  void publish_direction(const audio::ArrayChunk& chunk) {
    const std::optional<audio::SoundDirection> found =
        audio::locate_sound(audio::raw_microphones(chunk));
    if (!found) {
      return;
    }
    std_msgs::Int32 degrees;
    degrees.data = static_cast<int32_t>(std::lround(found->azimuth_rad * 180.0 / M_PI));
    direction_.publish(degrees);
    geometry_msgs::PoseStamped pose;
    pose.header.frame_id = kArrayFrame;
    pose.header.stamp =
        ros::Time((chunk.first_sample + static_cast<int64_t>(audio::kChunkSamples)) /
                  static_cast<double>(audio::kSampleRateHz));
    pose.pose.orientation.z = std::sin(found->azimuth_rad / 2.0);
    pose.pose.orientation.w = std::cos(found->azimuth_rad / 2.0);
    localization_.publish(pose);
  }

  ros::NodeHandle nh_;
  audio::AudioRunConfig run_;
  std::vector<audio::Wall> walls_;
  uint64_t seed_;
  std::shared_ptr<audio::SpeechSynthesizer> synthesizer_ =
      std::make_shared<audio::SpeechSynthesizer>();
  std::unique_ptr<audio::WorldAudio> audio_;
  std::optional<double> last_time_s_;
  std::optional<bool> voice_published_;
  std::array<ros::Publisher, 6> channels_;
  ros::Publisher raw_, voice_, direction_, localization_;
  ros::Subscriber world_state_;
};

}  // namespace
}  // namespace ari_social_sim::nodes

int main(int argc, char** argv) {
  using namespace ari_social_sim;
  return nodes::run_node(argc, argv, "audio_node", [] {
    ros::NodeHandle private_handle("~");
    audio::AudioRunConfig run =
        audio::AudioRunConfig::from_yaml(nodes::read_private_params(private_handle));
    if (run.scene.empty()) {
      run.scene = ros::package::getPath("ari_social_sim") + "/scenes/waiting_room.yaml";
    }
    const world::Scene scene = world::load_scene_file(run.scene);
    ROS_INFO("audio_node: %s, %zu walls, RT60 %.2f s, noise %.0f dBFS", run.scene.c_str(),
             audio::walls_of(scene.world).size(), run.room.rt60_s, run.room.noise_level_dbfs);
    nodes::AudioNode node(run, scene);
    ros::spin();
    return 0;
  });
}
