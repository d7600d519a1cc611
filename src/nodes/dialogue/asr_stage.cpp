#include "asr_stage.hpp"

#include <ros/time.h>
#include <std_msgs/Bool.h>
#include <std_msgs/String.h>

#include <algorithm>
#include <cmath>

#include "ari_social_sim/IdsList.h"
#include "ari_social_sim/LiveSpeech.h"
#include "ari_social_sim/dialogue/text.hpp"
#include "ari_social_sim/perception/perception_frame.hpp"

namespace ari_social_sim::nodes {
namespace {

std::string first_words(const std::vector<std::string>& words, size_t count) {
  std::string text;
  for (size_t i = 0; i < count && i < words.size(); ++i) {
    text += (i == 0 ? "" : " ") + words[i];
  }
  return text;
}

}  // namespace

AsrStage::AsrStage(ros::NodeHandle& nh, const dialogue::TurnTiming& timing,
                   std::vector<std::string> roles, std::vector<uint32_t> human_ids,
                   std::string language)
    : timing_(timing),
      roles_(std::move(roles)),
      human_ids_(std::move(human_ids)),
      language_(std::move(language)) {
  voices_tracked_ = nh.advertise<IdsList>("/humans/voices/tracked", 1, /*latch=*/true);
  persons_tracked_ = nh.advertise<IdsList>("/humans/persons/tracked", 1, /*latch=*/true);
  for (uint32_t id : human_ids_) {
    Voice voice;
    voice.id = voice_id(id);
    voice.speech = nh.advertise<LiveSpeech>("/humans/voices/" + voice.id + "/speech", 10);
    voice.is_speaking =
        nh.advertise<std_msgs::Bool>("/humans/voices/" + voice.id + "/is_speaking", 10, true);
    // REP-155 latches the person's voice_id and anonymous flags.
    const std::string person = "/humans/persons/" + perception::person_id_of(id);
    ros::Publisher voice_of = nh.advertise<std_msgs::String>(person + "/voice_id", 1, true);
    ros::Publisher anonymous = nh.advertise<std_msgs::Bool>(person + "/anonymous", 1, true);
    std_msgs::String voice_name;
    voice_name.data = voice.id;
    voice_of.publish(voice_name);
    std_msgs::Bool no;
    no.data = false;
    anonymous.publish(no);
    voice.is_speaking.publish(no);
    person_topics_.push_back(voice_of);
    person_topics_.push_back(anonymous);
    voices_.push_back(std::move(voice));
  }
  publish_tracked();
}

double AsrStage::now_s() const {
  return ros::Time::now().toSec();
}

bool AsrStage::has_listener() const {
  return std::any_of(voices_.begin(), voices_.end(),
                     [](const Voice& voice) { return voice.speech.getNumSubscribers() > 0; });
}

void AsrStage::publish_tracked() {
  IdsList voices;
  IdsList persons;
  voices.header.stamp = persons.header.stamp = ros::Time::now();
  for (size_t i = 0; i < voices_.size(); ++i) {
    voices.ids.push_back(voices_[i].id);
    persons.ids.push_back(perception::person_id_of(human_ids_[i]));
  }
  voices_tracked_.publish(voices);
  persons_tracked_.publish(persons);
}

void AsrStage::publish_speech(size_t voice, const std::string& incremental,
                              const std::string& final_text, double confidence) {
  LiveSpeech speech;
  speech.header.stamp = ros::Time::now();
  speech.incremental = incremental;
  speech.final = final_text;
  speech.confidence = confidence;
  speech.language = language_;
  voices_[voice].speech.publish(speech);
}

void AsrStage::start_human(const dialogue::Utterance& utterance, size_t human) {
  human_playing_ = true;
  human_start_s_ = now_s();
  human_duration_s_ = timing_.duration(utterance.text);
  words_published_ = 0;
  heard_voice_ = -1;
  heard_words_ = dialogue::split_words(utterance.heard.text);
  if (utterance.heard.dropped || heard_words_.empty()) {
    return;  // the ASR missed it: nothing is published, the time still passes
  }
  // The voice the system hears it from: the perceived speaker (maybe the other human).
  const auto role = std::find(roles_.begin(), roles_.end(), utterance.heard.speaker);
  heard_voice_ = static_cast<int>(role != roles_.end() ? role - roles_.begin() : human);
  heard_confidence_ = utterance.heard.confidence;
  std_msgs::Bool yes;
  yes.data = true;
  voices_[heard_voice_].is_speaking.publish(yes);
}

bool AsrStage::human_done() {
  if (!human_playing_) {
    return true;
  }
  const double elapsed = now_s() - human_start_s_;
  const bool over = elapsed >= human_duration_s_;
  if (heard_voice_ >= 0) {
    // Word k (from 1) is recognised at the end of its share of the utterance; the last one
    // comes with the final result instead.
    const size_t n = heard_words_.size();
    const auto recognised = static_cast<size_t>(std::floor(elapsed / human_duration_s_ * n));
    for (; words_published_ + 1 < n && words_published_ < recognised; ++words_published_) {
      publish_speech(heard_voice_, first_words(heard_words_, words_published_ + 1), "", 0.0);
    }
  }
  if (!over) {
    return false;
  }
  if (heard_voice_ >= 0) {
    publish_speech(heard_voice_, "", first_words(heard_words_, heard_words_.size()),
                   heard_confidence_);
    std_msgs::Bool no;
    no.data = false;
    voices_[heard_voice_].is_speaking.publish(no);
  }
  human_playing_ = false;
  return true;
}

void AsrStage::start_robot(const std::string& text) {
  robot_start_s_ = now_s();
  robot_duration_s_ = timing_.duration(text);
  robot_word_count_ = dialogue::split_words(text).size();
}

size_t AsrStage::robot_words_started() {
  const double per_word = robot_duration_s_ / static_cast<double>(robot_word_count_);
  const auto started = static_cast<size_t>(std::floor((now_s() - robot_start_s_) / per_word)) + 1;
  return std::min(started, robot_word_count_);
}

bool AsrStage::robot_done() {
  return now_s() >= robot_start_s_ + robot_duration_s_;
}

}  // namespace ari_social_sim::nodes
