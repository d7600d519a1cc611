#include <gtest/gtest.h>

#include <fstream>

#include "ari_social_sim/scenario/scenario.hpp"
#include "expect_config_error.hpp"

namespace ari_social_sim::scenario {
namespace {

const std::string kSource = ARI_SOURCE_DIR;

// A scenario file in the temporary folder: room_6x6, ARI, Ana (10) and Luc (11) in group 1, and
// the given script.
std::string write_scenario(const std::string& script, const std::string& scene_extra = "") {
  const std::string path = ::testing::TempDir() + "scenario_under_test.yaml";
  std::ofstream(path) << "world: " << kSource << "/worlds/room_6x6.yaml\nseed: 3\n"
                      << "ari: {position: [1, 5], orientation: -1.57}\n"
                      << "humans:\n"
                      << "  - {id: 10, name: Ana, position: [3, 3]}\n"
                      << "  - {id: 11, name: Luc, position: [4, 3]}\n"
                      << "groups:\n  - {id: 1, members: [10, 11], centre: [3.5, 3]}\n"
                      << scene_extra << "script:\n"
                      << script;
  return path;
}

// A script whose single state holds `state_body` (indented under `- name: s`).
std::string one_state(const std::string& state_body) {
  return "  time_limit: 30\n  start: s\n  states:\n    - name: s\n" + state_body;
}

void expect_rejected(const std::string& script, const std::vector<std::string>& fragments,
                     const std::string& scene_extra = "") {
  const std::string path = write_scenario(script, scene_extra);
  world::test::expect_config_error([&] { load_scenario_file(path); }, path, fragments);
}

// D6.4's GroupDiscussionScript: six states after looking, and a request to repeat what ARI did
// not understand.
TEST(Scenario, GroupDiscussionReadsAsTheSeedsSixStatesAfterLookingAndARepair) {
  const Scenario s = load_scenario_file(kSource + "/scenarios/group_discussion.yaml");
  EXPECT_EQ(s.name, "group_discussion");
  EXPECT_EQ(s.scene.humans.size(), 2u);
  ASSERT_TRUE(s.scene.ari.has_value());
  EXPECT_DOUBLE_EQ(s.scene.ari->pose.position.x(), 1.0);
  EXPECT_DOUBLE_EQ(s.script.time_limit_s, 120.0);
  ASSERT_EQ(s.script.states.size(), 8u);
  EXPECT_EQ(s.script.start, "look");
  const std::vector<std::string> names = {"look",      "grouping",    "ask_help",  "ask_time",
                                          "ask_again", "answer_time", "thank_ari", "leave"};
  for (size_t i = 0; i < names.size(); ++i) {
    EXPECT_EQ(s.script.states[i].name, names[i]);
  }
  const auto& seen = std::get<PerceivedGroupCondition>(s.script.states[0].transitions[0].when[0]);
  ASSERT_EQ(seen.members.size(), 2u);
  EXPECT_EQ(seen.members[1].human_id, 11u);
  const State& grouping = s.script.states[1];
  ASSERT_EQ(grouping.on_enter.size(), 1u);
  EXPECT_EQ(std::get<JoinGroupAction>(grouping.on_enter[0]).person, 11u);
  const auto& near_irene = std::get<DistanceCondition>(grouping.transitions[0].when[0]);
  EXPECT_TRUE(near_irene.from.is_ari());
  EXPECT_EQ(near_irene.to_agent->human_id, 11u);
  EXPECT_DOUBLE_EQ(near_irene.distance_m, 1.5);
  EXPECT_TRUE(near_irene.below);
  const auto& help = std::get<SayAction>(grouping.transitions[0].actions[0]);
  EXPECT_EQ(help.act, "QUESTION:HELP");
  EXPECT_EQ(grouping.transitions[0].next, "ask_help");
  const auto& failed = std::get<StopAction>(grouping.transitions[1].actions[0]);
  EXPECT_FALSE(failed.success);
  const auto& home = std::get<DistanceCondition>(s.script.states[7].transitions[0].when[0]);
  EXPECT_FALSE(home.to_agent.has_value());
  EXPECT_EQ(home.to_point, Eigen::Vector2d(1.0, 5.0));
  EXPECT_DOUBLE_EQ(home.distance_m, 0.5);
}

TEST(Scenario, EveryShippedScenarioLoads) {
  // name, humans in the scene, states, what it needs beyond the world
  const struct {
    const char* name;
    size_t humans, states;
    bool dialogue;
  } shipped[] = {{"group_discussion", 2, 8, false},
                 {"waiting_room", 6, 4, true},
                 {"corridor", 6, 1, false},
                 {"join_group", 0, 4, false},
                 {"join_conversation", 3, 7, false}};
  for (const auto& expected : shipped) {
    const Scenario s = load_scenario_file(kSource + "/scenarios/" + expected.name + ".yaml");
    EXPECT_EQ(s.scene.humans.size(), expected.humans) << expected.name;
    EXPECT_EQ(s.script.states.size(), expected.states) << expected.name;
    EXPECT_EQ(s.script.interfaces().dialogue, expected.dialogue) << expected.name;
  }
}

TEST(Scenario, GroupDiscussionNeedsSpeechPerceivedGroupsAndBothNavigationActions) {
  const ScriptInterfaces uses =
      load_scenario_file(kSource + "/scenarios/group_discussion.yaml").script.interfaces();
  EXPECT_TRUE(uses.text_to_speech);
  EXPECT_TRUE(uses.approach);
  EXPECT_TRUE(uses.move_base);
  EXPECT_TRUE(uses.perceived_groups);
  EXPECT_TRUE(uses.speech_recognition);  // ARI answers what it heard
}

TEST(Scenario, EveryConditionAndActionTypeReads) {
  const Scenario s = load_scenario_file(write_scenario(
      "  time_limit: 30\n  start: a\n"
      "  random_groups:\n"
      "    - {id: 2, first_human_id: 20, size: [2, 4], centre_min: [2, 2], centre_max: [3, 3]}\n"
      "  states:\n"
      "    - name: a\n"
      "      enter:\n"
      "        - {type: say, speaker: 10, act: greet(), text: Hello}\n"
      "        - {type: set_goal, who: 10, position: [2, 2], orientation: 1}\n"
      "        - {type: set_goal, who: ari, position: [1, 4]}\n"
      "        - {type: approach, person: 10}\n"
      "        - {type: join_group, person: 20}\n"
      "        - {type: cancel_navigation}\n"
      "        - {type: add_human, human: {id: 12, position: [5, 5], gender: male, goal: "
      "{position: [1, 1]}}}\n"
      "        - {type: remove_human, human: 12}\n"
      "        - {type: create_group, group: {id: 5, members: [10, 12], centre: [4, 4]}}\n"
      "        - {type: add_group_members, group: 5, members: [11]}\n"
      "        - {type: set_group_centre, group: 2, centre: [2, 2]}\n"
      "        - {type: set_posture, who: 11, posture: sitting}\n"
      "      transitions:\n"
      "        - when:\n"
      "            - {type: distance_above, from: 10, to: ari, distance: 2}\n"
      "            - {type: speech_finished, speaker: ari, act: 'inform*'}\n"
      "            - {type: goal_reached, who: 10, tolerance: 0.2}\n"
      "            - {type: goal_reached, who: ari}\n"
      "            - {type: navigation_failed}\n"
      "            - {type: time_elapsed, seconds: 3}\n"
      "            - {type: perceived_group, members: [ari, 10, 21]}\n"
      "            - {type: heard, act: 'greet*'}\n"
      "            - {type: floor_free, person: 10}\n"
      "            - {type: addressed}\n"
      "            - {type: not_understood}\n"
      "          do: [{type: stop, success: true, reason: done}]\n"
      "        - when: []\n"
      "          next: a\n"));
  const State& a = s.script.states[0];
  EXPECT_EQ(a.on_enter.size(), 12u);
  const auto& sits = std::get<SetPostureAction>(a.on_enter[11]);
  EXPECT_EQ(sits.human, 11u);
  EXPECT_EQ(sits.posture, world::Posture::kSitting);
  EXPECT_EQ(a.transitions[0].when.size(), 11u);
  EXPECT_EQ(std::get<FloorFreeCondition>(a.transitions[0].when[8]).person, 10u);
  EXPECT_TRUE(std::holds_alternative<AddressedCondition>(a.transitions[0].when[9]));
  EXPECT_TRUE(std::holds_alternative<NotUnderstoodCondition>(a.transitions[0].when[10]));
  EXPECT_EQ(std::get<HeardCondition>(a.transitions[0].when[7]).act, "greet*");
  EXPECT_TRUE(a.transitions[0].next.empty());
  EXPECT_TRUE(a.transitions[1].when.empty());
  const auto& added = std::get<AddHumanAction>(a.on_enter[6]).human;
  EXPECT_EQ(added.id, 12u);
  EXPECT_EQ(added.gender, model::Gender::kMale);
  ASSERT_TRUE(added.goal.has_value());
  EXPECT_DOUBLE_EQ(std::get<GoalReachedCondition>(a.transitions[0].when[2]).tolerance_m, 0.2);
  EXPECT_DOUBLE_EQ(std::get<GoalReachedCondition>(a.transitions[0].when[3]).tolerance_m, 0.3);
  const auto& group = std::get<PerceivedGroupCondition>(a.transitions[0].when[6]);
  ASSERT_EQ(group.members.size(), 3u);
  EXPECT_TRUE(group.members[0].is_ari());
  EXPECT_EQ(group.members[2].human_id, 21u);
  ASSERT_EQ(s.script.random_groups.size(), 1u);
  EXPECT_EQ(s.script.random_groups[0].max_size, 4u);
}

TEST(Scenario, AWorldNodeReadsTheSceneOfAScenarioFile) {
  const world::Scene scene = world::load_scene_file(kSource + "/scenarios/group_discussion.yaml");
  EXPECT_EQ(scene.humans.size(), 2u);
  EXPECT_EQ(scene.groups.size(), 1u);
}

TEST(Scenario, SceneErrorsNameTheSceneEntry) {
  expect_rejected(one_state(""), {"top level", "unknown field(s) colour"}, "colour: red\n");
  const std::string path = ::testing::TempDir() + "scenario_bad_scene.yaml";
  std::ofstream(path) << "world: nowhere.yaml\nseed: 1\nscript: {}\n";
  world::test::expect_config_error([&] { load_scenario_file(path); }, path,
                                   {"world", "cannot open"});
}

TEST(Scenario, ScriptStructureErrorsNameTheEntry) {
  expect_rejected("  start: s\n  states: [{name: s}]\n", {"script.time_limit", "required"});
  expect_rejected("  time_limit: -1\n  start: s\n  states: [{name: s}]\n",
                  {"script.time_limit", "(0, 86400]", "-1"});
  expect_rejected("  time_limit: 5\n  start: s\n  states: []\n",
                  {"script.states", "at least one state"});
  expect_rejected("  time_limit: 5\n  start: x\n  states: [{name: s}]\n",
                  {"script.start", "the name of a state (s)", "'x'"});
  expect_rejected("  time_limit: 5\n  start: s\n  states: [{name: s}, {name: s}]\n",
                  {"script.states[1].name", "no other state has", "'s'"});
  expect_rejected("  time_limit: 5\n  start: s\n  colour: red\n  states: [{name: s}]\n",
                  {"script", "unknown field(s) colour"});
  expect_rejected(one_state("      transitions: [{when: [], next: t}]\n"),
                  {"script.states[0].transitions[0].next", "the name of a state", "'t'"});
  expect_rejected(one_state("      transitions: [{when: []}]\n"),
                  {"script.states[0].transitions[0].next", "required"});
  expect_rejected(
      one_state("      transitions: [{when: [], do: [{type: stop, success: true}], next: s}]\n"),
      {"transitions[0].next", "no next state after a stop action"});
  expect_rejected(one_state("      transitions: [{do: [], next: s}]\n"),
                  {"transitions[0].when", "required"});
}

TEST(Scenario, ConditionErrorsNameTheCondition) {
  const auto when = [](const std::string& condition) {
    return one_state("      transitions: [{when: [" + condition + "], next: s}]\n");
  };
  const std::string at = "script.states[0].transitions[0].when[0]";
  expect_rejected(when("{type: near}"), {at + ".type", "one of distance_below", "'near'"});
  expect_rejected(when("{type: distance_below, from: ari, to: 10, distance: -1}"),
                  {at + ".distance", "> 0", "-1"});
  expect_rejected(when("{type: distance_below, from: ari, distance: 1}"),
                  {at + ".to", "exactly one", "neither"});
  expect_rejected(when("{type: distance_below, from: ari, to: 10, to_point: [1, 1], distance: 1}"),
                  {at + ".to", "exactly one", "both"});
  expect_rejected(when("{type: distance_below, from: 42, to: 10, distance: 1}"),
                  {at + ".from", "a human of the scene or one the script adds", "42"});
  expect_rejected(when("{type: speech_finished, speaker: ari}"), {at + ".act", "required"});
  expect_rejected(when("{type: goal_reached, who: ari, tolerance: 0.5}"),
                  {at + ".tolerance", "no tolerance for ARI"});
  expect_rejected(when("{type: time_elapsed, seconds: 2, minutes: 1}"),
                  {at, "unknown field(s) minutes"});
  expect_rejected(when("{type: perceived_group, members: [10, bob]}"),
                  {at + ".members", "ari or human ids", "'bob'"});
  expect_rejected(when("{type: heard}"), {at + ".act", "required"});
  expect_rejected(when("{type: not_understood, act: 'QUESTION:TIME'}"),
                  {at, "unknown field(s) act"});
  expect_rejected(when("{type: floor_free}"), {at + ".person", "required"});
  expect_rejected(when("{type: floor_free, person: 77}"), {at + ".person", "77"});
  // No human of the script says it: the state would wait for ever.
  expect_rejected(when("{type: heard, act: 'QUESTION:*'}"),
                  {"script.states[0].transitions[0].when: heard", "a line a human of the script",
                   "'QUESTION:*'"});
}

TEST(Scenario, ActionErrorsNameTheAction) {
  const auto enter = [](const std::string& action) {
    return one_state("      enter: [" + action + "]\n");
  };
  const std::string at = "script.states[0].enter[0]";
  expect_rejected(enter("{type: dance}"), {at + ".type", "one of say", "'dance'"});
  expect_rejected(enter("{type: say, speaker: ari, act: greet(), text: '  '}"),
                  {at + ".text", "a non-empty string"});
  expect_rejected(enter("{type: approach, person: ari}"), {at + ".person", "a human id", "ari"});
  expect_rejected(enter("{type: remove_human, human: 99}"),
                  {at + ".human", "a human of the scene or one the script adds", "99"});
  expect_rejected(enter("{type: set_group_centre, group: 7, centre: [1, 1]}"),
                  {at + ".group", "a group of the scene or one the script creates", "7"});
  expect_rejected(enter("{type: add_human, human: {id: 10, position: [5, 5]}}"),
                  {at + ".human.id", "used by no other human", "10"});
  expect_rejected(
      enter("{type: add_human, human: {id: 12, position: [5, 5], motion: {max_speed: 2}}}"),
      {at + ".human.motion", "default motion"});
  expect_rejected(enter("{type: add_human, human: {id: 12, position: [5, 5], reaction: avoid, "
                        "reaction_params: {avoid_distance: 3}}}"),
                  {at + ".human.reaction_params", "default reaction_params"});
  expect_rejected(enter("{type: add_human, human: {id: 12, position: [5, 5], reaction: shy}}"),
                  {at + ".human.reaction", "ignore, yield, curious, avoid or block", "'shy'"});
  expect_rejected(enter("{type: add_human, human: {id: 12, position: [5, 5], gaze: "
                        "{mean_duration: 1, directions: {distribution: normal, mean: 0, "
                        "stddev: 1}}}}"),
                  {at + ".human.gaze", "gaze targets", "directions"});
  expect_rejected(enter("{type: add_human, human: {id: 12, position: [5, 5], age: 300}}"),
                  {at + ".human.age", "[0, 130]", "300"});
  expect_rejected(enter("{type: create_group, group: {id: 1, members: [10], centre: [1, 1]}}"),
                  {at + ".group.id", "used by no other group", "1"});
  // /sim/create_group does not carry the stance: live it would take the default.
  expect_rejected(enter("{type: create_group, group: {id: 4, members: [10], centre: [1, 1], "
                        "facing_spread: 5}}"),
                  {at + ".group.facing_spread", "default facing_spread"});
  expect_rejected(enter("{type: create_group, group: {id: 4, members: [10], centre: [1, 1], "
                        "attention: 0.2}}"),
                  {at + ".group.attention", "default attention"});
  expect_rejected(enter("{type: create_group, group: {id: 4, members: [10], centre: [1, 1], "
                        "turnover: {join_rate: 1}}}"),
                  {at + ".group.turnover", "default turnover"});
  // Of the conversation, /sim/set_group_conversation carries the switch alone.
  expect_rejected(enter("{type: create_group, group: {id: 4, members: [10], centre: [1, 1], "
                        "conversation: {enabled: false, lapse_mean: 3}}}"),
                  {at + ".group.conversation", "lapse_mean"});
  expect_rejected(enter("{type: create_walking_group, group: {id: 1, members: [10, 11], goal: "
                        "{position: [1, 1]}}}"),
                  {at + ".group.id", "used by no other group", "1"});
  expect_rejected(enter("{type: create_walking_group, group: {id: 4, members: [10, 12], goal: "
                        "{position: [1, 1]}}}"),
                  {at + ".group.members", "a human of the scene", "12"});
  expect_rejected(enter("{type: create_walking_group, group: {id: 4, members: [10, 11], goal: "
                        "{position: [1, 1]}, wait_distance: 2}}"),
                  {at + ".group.wait_distance", "default wait_distance"});
  expect_rejected(enter("{type: create_walking_group, group: {id: 4, members: [10], goal: "
                        "{position: [1, 1]}}}"),
                  {at + ".group.members", "2 to 4 humans", "1"});
  expect_rejected(enter("{type: set_posture, who: 10, posture: lying}"),
                  {at + ".posture", "standing or sitting", "'lying'"});
  expect_rejected(enter("{type: set_posture, who: ari, posture: sitting}"),
                  {at + ".who", "a human id", "ari"});
  expect_rejected(enter("{type: set_posture, who: 99, posture: sitting}"),
                  {at + ".who", "a human of the scene or one the script adds", "99"});
  expect_rejected(enter("{type: stop, reason: why}"), {at + ".success", "required"});
}

TEST(Scenario, SpawnPositionsAreCheckedOnLoad) {
  const std::string path = ::testing::TempDir() + "scenario_overlap.yaml";
  std::ofstream(path) << "world: " << kSource << "/worlds/room_6x6.yaml\nseed: 1\n"
                      << "humans: [{id: 10, position: [3, 3]}, {id: 11, position: [3.1, 3]}]\n"
                      << "script:\n" + one_state("");
  world::test::expect_config_error([&] { load_scenario_file(path); }, path,
                                   {"humans[1]", "human 11", "overlap", "human 10"});
}

TEST(Scenario, LinesAboutAriNeedASceneWithAri) {
  const std::string path = ::testing::TempDir() + "scenario_without_ari.yaml";
  std::ofstream(path) << "world: " << kSource << "/worlds/room_6x6.yaml\nseed: 1\n"
                      << "humans: [{id: 10, position: [3, 3]}]\n"
                      << "script:\n" + one_state("      enter: [{type: approach, person: 10}]\n");
  world::test::expect_config_error([&] { load_scenario_file(path); }, path,
                                   {"script.states[0].enter[0].type", "a scene with ARI"});
}

TEST(Scenario, RandomGroupIdsMustNotClash) {
  expect_rejected(
      "  time_limit: 5\n  start: s\n  states: [{name: s}]\n"
      "  random_groups: [{id: 2, first_human_id: 9, size: [2, 3], centre_min: [2, 2], "
      "centre_max: [3, 3]}]\n",
      {"script.random_groups[0].first_human_id", "ids 9..11", "a clash on 10"});
  expect_rejected(
      "  time_limit: 5\n  start: s\n  states: [{name: s}]\n"
      "  random_groups: [{id: 2, first_human_id: 20, size: [4, 3], centre_min: [2, 2], "
      "centre_max: [3, 3]}]\n",
      {"script.random_groups[0].size", "1 <= min <= max", "[4, 3]"});
}

}  // namespace
}  // namespace ari_social_sim::scenario
