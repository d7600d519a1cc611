#pragma once

#include <map>
#include <ostream>
#include <string>
#include <vector>

#include "ari_social_sim/core/rng.hpp"
#include "ari_social_sim/core/yaml_map.hpp"

namespace ari_social_sim::dialogue {

/// The pseudo-intent of an unannotated utterance (MPGT lines without `#`).
constexpr const char* kNoIntent = "none";
/// The row that stands for every context without a row of its own.
constexpr const char* kAnyContext = "*";

/// A categorical distribution over intents (MPGT intents or `none`).
struct IntentDistribution {
  std::vector<std::string> intents;
  std::vector<double> probabilities;  ///< same length, each in [0, 1], summing to 1
  int count{0};                       ///< observations it was fitted on

  const std::string& sample(core::Rng& rng) const;
  double probability_of(const std::string& intent) const;
};

/// P(next intent | context intent), one row per context plus the `*` row.
struct ConditionalTable {
  std::map<std::string, IntentDistribution> rows;

  /// The row for `context`, or the `*` row.
  const IntentDistribution& row(const std::string& context) const;
};

/// Fitted behaviour of one human role (patient, companion, ...).
struct RoleModel {
  IntentDistribution opening;    ///< first human utterance when the humans open the dialogue
  ConditionalTable after_robot;  ///< P(intent | ARI's last first intent)
  ConditionalTable after_other;  ///< P(intent | the other human's utterance addressed to us)
  ConditionalTable after_self;   ///< P(intent | own previous utterance, keeping the floor)
  /// P(addressed to the other human | own intent), `*` for intents without an entry.
  std::map<std::string, double> to_other;
  double keep_floor{0.1};  ///< P(same human speaks again after an utterance to ARI)

  double to_other_probability(const std::string& intent) const;
};

/// How many goals a dialogue has and who owns them, fitted to the MPGT goal labels.
struct GoalCountModel {
  std::vector<unsigned> counts;       ///< distinct goals per dialogue
  std::vector<double> probabilities;  ///< their frequencies
  double joint_share{0.3};            ///< share of goals owned by both humans
};

/// The probability tables of the user simulation (config/dialogue/mpgt_user_model.yaml), written
/// by fit_dialogue_model and constant once loaded.
struct UserModel {
  std::map<std::string, RoleModel> roles;
  double robot_opens{0.7};     ///< P(ARI speaks first)
  double same_responder{0.7};  ///< P(the human ARI answered is the one who replies)
  GoalCountModel goals;
  std::string provenance;  ///< how it was fitted, one line

  /// Throws core::ConfigError naming `source` and the role when `role` has no tables.
  const RoleModel& role(const std::string& role, const std::string& source) const;

  /// Reads a model file. Throws core::ConfigError naming the file and entry when a table has an
  /// unknown intent, probabilities outside [0, 1] or not summing to 1 (within 1e-6), lists of
  /// different lengths, a missing `*` row, or a role twice.
  static UserModel load(const std::string& file_path);
  static UserModel parse(const core::YamlMap& map);
  /// Writes the YAML `load` reads, probabilities with 6 decimals adjusted to sum to 1 exactly.
  void write(std::ostream& out) const;
};

}  // namespace ari_social_sim::dialogue
