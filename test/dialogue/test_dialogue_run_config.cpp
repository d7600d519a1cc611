#include <gtest/gtest.h>

#include "ari_social_sim/dialogue/dialogue_run_config.hpp"
#include "test_helpers.hpp"

namespace ari_social_sim::dialogue {
namespace {

using testing::expect_config_error;

DialogueRunConfig read(const std::string& yaml) {
  return DialogueRunConfig::from_yaml(core::YamlMap::parse(yaml, "/dialogue_node parameter"));
}

TEST(DialogueRunConfig, ReadsEveryParameter) {
  const DialogueRunConfig c = read(
      "{mode: user_bot, config: /tmp/s.yaml, seed: 7, dialogues: 3, dialogue_pause: 1.5, "
      "robot_silence: 2.0, human_ids: [10, 11], language: fr-FR}");
  EXPECT_EQ(c.mode, DialogueMode::kUserBot);
  EXPECT_EQ(c.config, "/tmp/s.yaml");
  EXPECT_EQ(c.seed, 7u);
  EXPECT_EQ(c.dialogues, 3u);
  EXPECT_DOUBLE_EQ(c.dialogue_pause_s, 1.5);
  EXPECT_DOUBLE_EQ(c.live.robot_silence_s, 2.0);
  EXPECT_EQ(c.human_ids, (std::vector<unsigned>{10, 11}));
  EXPECT_EQ(c.language, "fr-FR");
  // Defaults: seed 1, endless dialogues 5 s apart, 3 s of silence, ids from the world.
  const DialogueRunConfig d = read("{mode: world}");
  EXPECT_EQ(d.seed, 1u);
  EXPECT_EQ(d.dialogues, 0u);
  EXPECT_DOUBLE_EQ(d.dialogue_pause_s, 5.0);
  EXPECT_DOUBLE_EQ(d.live.robot_silence_s, 3.0);
  EXPECT_TRUE(d.human_ids.empty());
  EXPECT_STREQ(to_string(read("{mode: rl_env}").mode), "rl_env");
}

TEST(DialogueRunConfig, BadParametersNameThemselves) {
  expect_config_error([] { read("{seed: 1}"); }, {"/dialogue_node parameter", "mode"});
  expect_config_error([] { read("{mode: chat}"); },
                      {"mode", "world, rl_env or user_bot", "'chat'"});
  expect_config_error([] { read("{mode: world, robot_silence: 0}"); }, {"robot_silence", "> 0"});
  expect_config_error([] { read("{mode: world, seed: -3}"); }, {"seed"});
  expect_config_error([] { read("{mode: world, dialogue_pause: -1}"); }, {"dialogue_pause"});
  expect_config_error([] { read("{mode: world, langage: en}"); }, {"langage"});
}

TEST(DialogueRunConfig, HumanIdsNeedOneDistinctIdPerRole) {
  const std::vector<std::string> roles{"patient", "companion"};
  read("{mode: world}").check_human_ids(roles, "p");
  read("{mode: world, human_ids: [10, 11]}").check_human_ids(roles, "p");
  expect_config_error([&] { read("{mode: world, human_ids: [10]}").check_human_ids(roles, "p"); },
                      {"p: human_ids", "patient, companion", "got 1 ids"});
  expect_config_error(
      [&] { read("{mode: world, human_ids: [10, 10]}").check_human_ids(roles, "p"); },
      {"human_ids"});
  expect_config_error(
      [&] { read("{mode: world, human_ids: [0, 10]}").check_human_ids(roles, "p"); },
      {"human_ids"});
}

TEST(DialogueRunConfig, ValidateRefusesABadValueBuiltInCode) {
  DialogueRunConfig config;
  EXPECT_NO_THROW(config.validate());
  config.language = "";
  expect_config_error([&] { config.validate(); },
                      {"DialogueRunConfig: language", "an IETF language tag", "got ''"});
  config = DialogueRunConfig{};
  config.live.robot_silence_s = 0.0;
  expect_config_error([&] { config.validate(); },
                      {"DialogueRunConfig: robot_silence", "> 0", "got 0"});
}

}  // namespace
}  // namespace ari_social_sim::dialogue
