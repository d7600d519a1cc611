#include "ari_social_sim/perception/perception_config.hpp"

#include <cmath>
#include <set>
#include <sstream>
#include <type_traits>

#include "ari_social_sim/core/error.hpp"

namespace ari_social_sim::perception {
namespace {

constexpr char kSource[] = "perception config";

std::string join_path(const std::string& path, const char* name) {
  return path.empty() ? name : path + "." + name;
}

// Reads each visited field from a mapping, each optional (the struct's value is the default);
// sections recurse into nested mappings, each closed with finish() so unknown keys are errors.
class FieldReader {
 public:
  explicit FieldReader(const core::YamlMap& map) : map_(map) {}

  template <class T>
  void field(const char* name, T& value, const core::Bounds& bounds = {}) {
    value = map_.optional<T>(name, value, bounds);
  }
  template <class S>
  void section(const char* name, S& section) {
    if (!map_.has(name)) {
      return;
    }
    const core::YamlMap nested = map_.map(name);
    FieldReader reader(nested);
    section.visit(reader);
    nested.finish();
  }

 private:
  const core::YamlMap& map_;
};

// Writes each visited field into a YAML mapping.
class FieldWriter {
 public:
  YAML::Node node{YAML::NodeType::Map};

  template <class T>
  void field(const char* name, T& value, const core::Bounds& = {}) {
    if constexpr (std::is_same_v<T, double>) {
      // Full precision, so that reading back gives the same double.
      std::ostringstream text;
      text.precision(17);
      text << value;
      node[name] = text.str();
    } else {
      node[name] = value;
    }
  }
  template <class S>
  void section(const char* name, S& section) {
    FieldWriter nested;
    section.visit(nested);
    node[name] = nested.node;
  }
};

// Checks every visited number against its bounds, naming the field path.
class BoundsChecker {
 public:
  explicit BoundsChecker(std::string path = "") : path_(std::move(path)) {}

  template <class T>
  void field(const char* name, T& value, const core::Bounds& bounds = {}) {
    if constexpr (std::is_arithmetic_v<T> && !std::is_same_v<T, bool>) {
      check(name, static_cast<double>(value), bounds);
    } else if constexpr (std::is_same_v<T, std::vector<double>>) {
      for (double item : value) {
        check(name, item, bounds);
      }
    }
  }
  template <class S>
  void section(const char* name, S& section) {
    BoundsChecker nested(join_path(path_, name));
    section.visit(nested);
  }

 private:
  void check(const char* name, double value, const core::Bounds& bounds) const {
    if (!bounds.contains(value)) {
      std::ostringstream got;
      got << value;
      throw core::ConfigError(std::string(kSource) + ": " + join_path(path_, name) +
                              ": expected a number " + bounds.describe() + ", got " + got.str());
    }
  }

  std::string path_;
};

[[noreturn]] void fail(const std::string& field, const std::string& message) {
  throw core::ConfigError(std::string(kSource) + ": " + field + ": " + message);
}

void check_confusion(const EmotionConfusion& confusion) {
  const std::pair<const char*, const std::vector<double>*> rows[] = {
      {"neutral", &confusion.neutral},
      {"happy", &confusion.happy},
      {"angry", &confusion.angry},
      {"disturbed", &confusion.disturbed}};
  for (const auto& [name, row] : rows) {
    const std::string field = std::string("face_errors.emotion_confusion.") + name;
    if (row->size() != 4) {
      fail(field, "expected 4 probabilities (neutral, happy, angry, disturbed), got " +
                      std::to_string(row->size()));
    }
    const double sum = (*row)[0] + (*row)[1] + (*row)[2] + (*row)[3];
    if (std::abs(sum - 1.0) > 1e-6) {
      fail(field, "expected probabilities summing to 1, got a sum of " + std::to_string(sum));
    }
  }
}

void check_speech(const SpeechErrors& speech) {
  const double shares = speech.substitution_share + speech.deletion_share + speech.insertion_share;
  if (std::abs(shares - 1.0) > 1e-6) {
    fail("speech_errors.substitution_share",
         "expected substitution_share + deletion_share + insertion_share = 1, got " +
             std::to_string(shares));
  }
  const bool draws_words =
      speech.word_error_rate > 0.0 && speech.substitution_share + speech.insertion_share > 0.0;
  const std::set<std::string> distinct(speech.vocabulary.begin(), speech.vocabulary.end());
  if (draws_words && distinct.size() < 2) {
    fail("speech_errors.vocabulary",
         "expected at least two different words (substitutions and "
         "insertions draw from it), got " +
             std::to_string(distinct.size()));
  }
  for (const std::string& word : speech.vocabulary) {
    if (word.empty() || word.find(' ') != std::string::npos) {
      fail("speech_errors.vocabulary", "expected single words, got '" + word + "'");
    }
  }
}

}  // namespace

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

void PerceptionConfig::validate() const {
  PerceptionConfig copy = *this;
  BoundsChecker checker;
  copy.visit(checker);
  check_confusion(face_errors.emotion_confusion);
  check_speech(speech_errors);
  if (persons.id_style != "human" && persons.id_style != "random") {
    fail("persons.id_style", "expected human or random, got '" + persons.id_style + "'");
  }
  if (persons.forget_after_s < persons.location_decay_s) {
    fail("persons.forget_after", "expected at least location_decay (" +
                                     std::to_string(persons.location_decay_s) + "), got " +
                                     std::to_string(persons.forget_after_s));
  }
  if (!(persons.personal_distance_m < persons.social_distance_m &&
        persons.social_distance_m < persons.public_distance_m)) {
    fail("persons.social_distance",
         "expected personal_distance < social_distance < public_distance, got " +
             std::to_string(persons.personal_distance_m) + ", " +
             std::to_string(persons.social_distance_m) + ", " +
             std::to_string(persons.public_distance_m));
  }
  if (human_model.eye_height_m <= human_model.hip_height_m) {
    fail("human_model.eye_height", "expected more than hip_height (" +
                                       std::to_string(human_model.hip_height_m) + "), got " +
                                       std::to_string(human_model.eye_height_m));
  }
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
  PerceptionConfig config;
  FieldReader reader(map);
  config.visit(reader);
  map.finish();
  try {
    config.validate();
  } catch (const core::ConfigError& e) {
    // Cross-field errors are found after reading: name the file instead of the generic source.
    std::string message = e.what();
    const std::string generic = std::string(kSource) + ": ";
    if (message.rfind(generic, 0) == 0) {
      message = map.source() + ": " + message.substr(generic.size());
    }
    throw core::ConfigError(message);
  }
  return config;
}

PerceptionConfig PerceptionConfig::load_file(const std::string& path) {
  return from_yaml(core::YamlMap::load_file(path));
}

std::string PerceptionConfig::to_yaml() const {
  PerceptionConfig copy = *this;
  FieldWriter writer;
  copy.visit(writer);
  YAML::Emitter out;
  out << writer.node;
  return out.c_str();
}

}  // namespace ari_social_sim::perception
