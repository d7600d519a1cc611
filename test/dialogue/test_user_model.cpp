#include <gtest/gtest.h>

#include <sstream>

#include "ari_social_sim/dialogue/user_model.hpp"
#include "test_helpers.hpp"

namespace ari_social_sim::dialogue {
namespace {

using testing::config_path;
using testing::expect_config_error;
using testing::replace_once;

std::string role_text(const std::string& name, const std::string& after_robot_p) {
  return "  - role: " + name +
         "\n"
         "    keep_floor: 0.2\n"
         "    opening: {next: [request, none], p: [0.5, 0.5]}\n"
         "    after_robot:\n"
         "      - {after: inform, next: [thank, request], p: " +
         after_robot_p +
         "}\n"
         "      - {after: '*', next: [request], p: [1.0]}\n"
         "    after_other:\n"
         "      - {after: '*', next: [none], p: [1.0]}\n"
         "    after_self:\n"
         "      - {after: '*', next: [request], p: [1.0]}\n"
         "    to_other: {intents: ['*'], p: [0.3]}\n";
}

std::string model_text(const std::string& roles) {
  return "robot_opens: 0.7\nsame_responder: 0.6\n"
         "goals: {counts: [1, 3], p: [0.25, 0.75], joint_share: 0.2}\nroles:\n" +
         roles;
}

TEST(UserModel, ParsesAndSamplesRows) {
  const UserModel model =
      UserModel::parse(core::YamlMap::parse(model_text(role_text("patient", "[0.8, 0.2]")), "m"));
  const RoleModel& patient = model.role("patient", "m");
  EXPECT_DOUBLE_EQ(patient.after_robot.row("inform").probability_of("thank"), 0.8);
  // A context without its own row falls back to `*`.
  EXPECT_DOUBLE_EQ(patient.after_robot.row("greet").probability_of("request"), 1.0);
  core::Rng rng(3);
  int thanks = 0;
  for (int i = 0; i < 10000; ++i) {
    thanks += patient.after_robot.row("inform").sample(rng) == "thank" ? 1 : 0;
  }
  // 10 000 draws at 0.8: sd 0.004.
  EXPECT_NEAR(thanks / 10000.0, 0.8, 0.015);
  EXPECT_DOUBLE_EQ(patient.to_other_probability("acknowledge"), 0.3);
}

TEST(UserModel, UnknownIntentNamesFileAndEntry) {
  const std::string text = model_text(role_text("patient", "[0.8, 0.2]"));
  const std::string bad = replace_once(text, "[thank, request]", "[thank, requets]");
  expect_config_error([&] { UserModel::parse(core::YamlMap::parse(bad, "model.yaml")); },
                      {"model.yaml", "roles[0].after_robot[0].next", "unknown intent 'requets'"});
}

TEST(UserModel, ProbabilitiesNotSummingToOneNameFileAndEntry) {
  // 0.8 + 0.3 = 1.1.
  const std::string text = model_text(role_text("patient", "[0.8, 0.3]"));
  expect_config_error([&] { UserModel::parse(core::YamlMap::parse(text, "model.yaml")); },
                      {"model.yaml", "roles[0].after_robot[0].p", "summing to 1", "1.100000"});
}

TEST(UserModel, MissingRoleNamesFileAndRole) {
  const UserModel model = UserModel::parse(
      core::YamlMap::parse(model_text(role_text("patient", "[0.8, 0.2]")), "model.yaml"));
  expect_config_error([&] { model.role("companion", "model.yaml"); },
                      {"model.yaml", "missing role 'companion'", "patient"});
}

TEST(UserModel, MissingAnyRowIsAnError) {
  const std::string text = replace_once(model_text(role_text("patient", "[0.8, 0.2]")),
                                        "{after: '*', next: [none]", "{after: none, next: [none]");
  expect_config_error([&] { UserModel::parse(core::YamlMap::parse(text, "m.yaml")); },
                      {"m.yaml", "roles[0].after_other", "after: '*'"});
}

TEST(UserModel, FittedFileLoadsAndWriteRoundTrips) {
  const UserModel model = UserModel::load(config_path("mpgt_user_model.yaml"));
  EXPECT_EQ(model.roles.size(), 2u);
  std::ostringstream out;
  model.write(out);
  const UserModel again = UserModel::parse(core::YamlMap::parse(out.str(), "written"));
  EXPECT_DOUBLE_EQ(again.robot_opens, model.robot_opens);
  EXPECT_EQ(again.roles.at("patient").after_robot.rows.size(),
            model.roles.at("patient").after_robot.rows.size());
}

}  // namespace
}  // namespace ari_social_sim::dialogue
