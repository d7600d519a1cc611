#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include "../common/data_sets.hpp"
#include "ari_social_sim/dialogue/dialogue_config.hpp"
#include "test_helpers.hpp"

namespace ari_social_sim::dialogue {
namespace {

using testing::config_path;
using testing::expect_config_error;
using testing::ScopedEnvironment;

std::string write_temp(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

// Settings read from `path` with the shipped domain, model and templates.
DialogueConfig load_with_shipped_files(const std::string& path) {
  DialogueConfig config = DialogueConfig::load(path);
  config.domain_file = config_path("hospital_domain.yaml");
  config.model_file = config_path("mpgt_user_model.yaml");
  config.templates_file = config_path("nlg_templates.yaml");
  return config;
}

TEST(DialogueConfig, ShippedSettingsRunOnTheRepositoryAlone) {
  const ScopedEnvironment no_corpus("ARI_MPGT_DIR", std::nullopt);
  const DialogueConfig config = DialogueConfig::load(config_path("simulation.yaml"));
  EXPECT_EQ(config.domain_file, config_path("hospital_domain.yaml"));
  EXPECT_EQ(config.nlg, NlgMode::kTemplate);
  EXPECT_EQ(config.corpus_dir, "");
  EXPECT_EQ(config.users.roles, (std::vector<std::string>{"patient", "companion"}));
  EXPECT_EQ(config.reward.max_turns, 40u);
  const auto setup = DialogueSetup::create(config);
  EXPECT_FALSE(setup->corpus.has_value());
  EXPECT_EQ(setup->corpus_or_null(), nullptr);
  core::Rng rng(1);
  EXPECT_FALSE(setup->nlg->realise(false, {parse_act("thank()", "t")}, rng).empty());
}

TEST(DialogueConfig, RetrievalWithoutACorpusSaysHowToGetOne) {
  const ScopedEnvironment no_corpus("ARI_MPGT_DIR", std::nullopt);
  const std::string path = write_temp("retrieval.yaml", "nlg: retrieval\n");
  const DialogueConfig config = load_with_shipped_files(path);
  expect_config_error([&] { DialogueSetup::create(config); },
                      {path + ": nlg: retrieval needs the MPGT corpus", "corpus_dir",
                       "ARI_MPGT_DIR", "scripts/fetch_data.sh", "nlg: template"});
}

TEST(DialogueConfig, ACorpusFolderThatIsMissingIsAnErrorNamingIt) {
  DialogueConfig config = DialogueConfig::defaults(ARI_DIALOGUE_CONFIG_DIR);
  const std::string missing = ::testing::TempDir() + "no_mpgt_here";
  {
    const ScopedEnvironment corpus("ARI_MPGT_DIR", missing);
    expect_config_error([&] { DialogueSetup::create(config); },
                        {"ARI_MPGT_DIR (DialogueConfig: corpus_dir is empty): " + missing,
                         "expected the folder of the MPGT corpus's convo*.txt files",
                         "got nothing (no such path)"});
  }
  const std::string path = write_temp("corpus.yaml", "corpus_dir: no_mpgt_here\n");
  config = load_with_shipped_files(path);
  expect_config_error([&] { DialogueSetup::create(config); },
                      {path + ": corpus_dir: " + missing, "got nothing (no such path)"});
}

TEST(DialogueConfig, ACorpusPointedAtIsLoaded) {
  ARI_SKIP_WITHOUT_DATA_SET(kMpgtDataSet);
  DialogueConfig config = DialogueConfig::defaults(ARI_DIALOGUE_CONFIG_DIR);
  config.corpus_dir = core::data_set_dir(kMpgtDataSet);
  config.nlg = NlgMode::kRetrieval;
  const auto setup = DialogueSetup::create(config);
  ASSERT_TRUE(setup->corpus.has_value());
  EXPECT_EQ(setup->corpus->dialogues.size(), 29u);
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
