#include "ari_social_sim/perception/perception_config.hpp"

#include <numeric>
#include <set>

#include "ari_social_sim/core/config_check.hpp"
#include "ari_social_sim/core/config_reader.hpp"
#include "ari_social_sim/core/config_writer.hpp"

namespace ari_social_sim::perception {

bool EmotionConfusion::is_distribution(const std::vector<double>& row) {
  return row.size() == 4 && std::abs(std::accumulate(row.begin(), row.end(), 0.0) - 1.0) <= 1e-6;
}

std::string EmotionConfusion::distribution_problem(const std::vector<double>& row) {
  if (row.size() != 4) {
    return std::to_string(row.size()) + " probabilities";
  }
  return "a sum of " + core::number_text(std::accumulate(row.begin(), row.end(), 0.0));
}

const std::vector<double>& EmotionConfusion::row(model::Emotion truth) const {
  switch (truth) {
    case model::Emotion::kHappy:
      return happy;
    case model::Emotion::kAngry:
      return angry;
    case model::Emotion::kDisturbed:
      return disturbed;
    case model::Emotion::kNeutral:
    default:
      return neutral;
  }
}

EmotionConfusion EmotionConfusion::identity() {
  return {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
}

size_t SpeechErrors::distinct_words() const {
  return std::set<std::string>(vocabulary.begin(), vocabulary.end()).size();
}

std::string SpeechErrors::compound_word() const {
  for (const std::string& word : vocabulary) {
    if (word.empty() || word.find(' ') != std::string::npos) {
      return word;
    }
  }
  return "";
}

void GroupConfig::validate() const {
  core::check_fields(*this, "GroupConfig");
}

void PerceptionConfig::validate() const {
  core::check_fields(*this, "PerceptionConfig");
}

PerceptionConfig PerceptionConfig::without_errors() const {
  PerceptionConfig config = *this;
  config.errors_enabled = false;
  for (DetectionErrors* detection :
       {&config.body_errors.detection, &config.face_errors.detection}) {
    *detection = DetectionErrors{0.0, 0.0, 0.0, detection->fov_border_deg, 0.0, 0.0, 0.0, 0.0};
  }
  config.body_errors.pose = PoseNoise{0.0, 0.0, 0.0, 0.0};
  config.face_errors.pose = PoseNoise{0.0, 0.0, 0.0, 0.0};
  config.face_errors.age_noise_years = 0.0;
  config.face_errors.gender_error_rate = 0.0;
  config.face_errors.mask_error_rate = 0.0;
  config.face_errors.emotion_confusion = EmotionConfusion::identity();
  config.speech_errors.word_error_rate = 0.0;
  config.speech_errors.misattribution_rate = 0.0;
  config.matchers.recognition_rate = 1.0;
  config.matchers.confidence_noise = 0.0;
  return config;
}

PerceptionConfig PerceptionConfig::from_yaml(const core::YamlMap& map) {
  return core::read_fields<PerceptionConfig>(map);
}

PerceptionConfig PerceptionConfig::load_file(const std::string& path) {
  return from_yaml(core::YamlMap::load_file(path));
}

std::string PerceptionConfig::to_yaml() const {
  return core::write_fields(*this);
}

}  // namespace ari_social_sim::perception
