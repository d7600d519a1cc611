#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include "ari_social_sim/dialogue/dialogue_config.hpp"
#include "test_helpers.hpp"

namespace ari_social_sim::dialogue {
namespace {

using testing::config_path;
using testing::expect_config_error;

std::string write_temp(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

TEST(DialogueConfig, ShippedSettingsLoadAndResolvePaths) {
  const DialogueConfig config = DialogueConfig::load(config_path("simulation.yaml"));
  EXPECT_EQ(config.domain_file, config_path("hospital_domain.yaml"));
  EXPECT_EQ(config.nlg, NlgMode::kRetrieval);
  EXPECT_EQ(config.users.roles, (std::vector<std::string>{"patient", "companion"}));
  EXPECT_EQ(config.reward.max_turns, 40u);
  const auto setup = DialogueSetup::create(config);
  EXPECT_EQ(setup->corpus.dialogues.size(), 29u);
}

TEST(DialogueConfig, UnknownFieldAndBadModeNameTheFile) {
  const std::string typo = write_temp("typo.yaml", "nlg: template\nrewrad: {max_turns: 3}\n");
  expect_config_error([&] { DialogueConfig::load(typo); }, {"typo.yaml", "rewrad"});
  const std::string mode = write_temp("mode.yaml", "nlg: neural\n");
  expect_config_error([&] { DialogueConfig::load(mode); }, {"mode.yaml: nlg", "neural"});
}

TEST(DialogueConfig, RoleMissingFromTheModelNamesFileAndRole) {
  // A third role, added by configuration, needs its table in the model file.
  DialogueConfig config = DialogueConfig::defaults(ARI_DIALOGUE_CONFIG_DIR);
  config.users.roles = {"patient", "companion", "visitor"};
  expect_config_error([&] { DialogueSetup::create(config); },
                      {"mpgt_user_model.yaml", "missing role 'visitor'"});
}

TEST(DialogueConfig, UserSettingsAreValidated) {
  const std::string path = write_temp("users.yaml", "users: {min_patience: 6, max_patience: 4}\n");
  expect_config_error([&] { DialogueConfig::load(path); },
                      {"users.yaml: users.max_patience", "min_patience (6)", "4"});
}

TEST(DialogueConfig, ValidateRefusesABadValueBuiltInCode) {
  DialogueConfig config = DialogueConfig::defaults(ARI_DIALOGUE_CONFIG_DIR);
  EXPECT_NO_THROW(config.validate());
  config.users.min_patience = 6;
  config.users.max_patience = 4;
  // The setup checks the settings it is given before it loads any file.
  expect_config_error([&] { DialogueSetup::create(config); },
                      {"DialogueConfig: users.max_patience", ">= min_patience (6)", "got 4"});
  config = DialogueConfig::defaults(ARI_DIALOGUE_CONFIG_DIR);
  config.users.roles = {"patient", "ARI"};
  expect_config_error([&] { config.validate(); }, {"DialogueConfig: users.roles", "'ARI'"});
  config.users.roles = {"patient"};
  config.timing.gap_sd_s = -0.1;
  expect_config_error([&] { config.validate(); },
                      {"DialogueConfig: timing.gap_sd_s", ">= 0", "got -0.1"});
}

TEST(UserSimulationConfig, ValidateRefusesABadValueBuiltInCode) {
  UserSimulationConfig config;
  EXPECT_NO_THROW(config.validate());
  config.roles = {"patient", "patient"};
  expect_config_error([&] { config.validate(); },
                      {"UserSimulationConfig: roles", "distinct", "'patient'"});
  config.roles.clear();
  expect_config_error([&] { config.validate(); }, {"UserSimulationConfig: roles", "got []"});
}

}  // namespace
}  // namespace ari_social_sim::dialogue
