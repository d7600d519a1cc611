#include <gtest/gtest.h>

#include "ari_social_sim/batch/episode_csv.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/scenario/script_runner.hpp"

namespace ari_social_sim::scenario {
namespace {

const std::string kSource = ARI_SOURCE_DIR;

// Records every command as a line of text; refuses those whose text starts with `refuse_`.
class RecordingCommands : public Commands {
 public:
  std::vector<std::string> log;
  std::string refuse;

  void say(const AgentRef& speaker, const std::string& act, const std::string&) override {
    record("say " + speaker.describe() + " " + act);
  }
  void set_human_goal(model::ObjectId human, const core::Pose2& goal) override {
    record("goal " + std::to_string(human) + " " + std::to_string(goal.position.x()));
  }
  void navigate(const core::Pose2& goal) override {
    record("navigate " + std::to_string(goal.position.x()));
  }
  void approach(const std::string& person_id, bool join_group) override {
    record((join_group ? "join " : "approach ") + person_id);
  }
  void fail_navigation(const std::string& reason) override { record("fail: " + reason); }
  void cancel_navigation() override { record("cancel"); }
  void add_human(const world::HumanSpec& spec) override {
    record("add " + std::to_string(spec.id));
  }
  void remove_human(model::ObjectId human) override { record("remove " + std::to_string(human)); }
  void create_group(const world::GroupSpec& spec) override {
    record("group " + std::to_string(spec.id) + " of " + std::to_string(spec.members.size()));
  }
  void create_walking_group(const world::WalkingGroupSpec& spec) override {
    record("walking group " + std::to_string(spec.id) + " of " +
           std::to_string(spec.members.size()));
  }
  void add_group_members(model::ObjectId group, const std::vector<model::ObjectId>&) override {
    record("members " + std::to_string(group));
  }
  void set_group_centre(model::ObjectId group, const Eigen::Vector2d&) override {
    record("centre " + std::to_string(group));
  }
  void set_group_arrangement(model::ObjectId group, model::Arrangement arrangement,
                             std::optional<double>) override {
    record("arrangement " + std::to_string(group) + " " + model::to_string(arrangement));
  }
  void leave_group(model::ObjectId agent) override { record("leave " + std::to_string(agent)); }
  void set_posture(model::ObjectId human, world::Posture posture) override {
    record("posture " + std::to_string(human) + " " + world::posture_name(posture));
  }

 private:
  void record(const std::string& line) {
    if (!refuse.empty() && line.rfind(refuse, 0) == 0) {
      throw core::RequestError("no human with id 99");
    }
    log.push_back(line);
  }
};

// Perception's ids of Paul (10) and Irene (11), of the form a person manager gives.
const std::string kPaulPerson = "anonymous_person_pauls";
const std::string kIrenePerson = "anonymous_person_irene";

// A hand-made world: ARI and Paul (10) and Irene (11) where the test puts them; perception
// reports them under anonymous ids, as a group.
struct Stage {
  Observations obs;

  Stage() {
    obs.world.ari = world::AriSnapshot{};
    obs.world.ari->pose.position = {1.0, 5.0};
    for (model::ObjectId id : {10u, 11u}) {
      world::HumanSnapshot human;
      human.id = id;
      human.pose.position = id == 10 ? Eigen::Vector2d(3.0, 2.0) : Eigen::Vector2d(4.0, 2.0);
      obs.world.humans.push_back(human);
    }
    obs.person_ids = {{10, kPaulPerson}, {11, kIrenePerson}};
    obs.perceived_groups.push_back({"group1", {AgentRef::human(10), AgentRef::human(11)}});
  }
  world::SpeechSnapshot& speech(const AgentRef& who) {
    return who.is_ari() ? obs.world.ari->speech : obs.world.humans[who.human_id - 10].speech;
  }
  // `who` starts saying `act` now.
  void start(const AgentRef& who, const std::string& act, const std::string& text = "words") {
    speech(who) = {act, text, text, 0, true, obs.world.time_s, "", ""};
  }
  void stop(const AgentRef& who) {
    world::SpeechSnapshot& s = speech(who);
    s = {"", "", "", 0, false, 0.0, s.act, s.content};
  }
  void tick(ScriptRunner& runner, Commands& commands, double dt_s = 0.05) {
    obs.world.time_s += dt_s;
    ++obs.world.step;
    runner.update(obs, commands);
  }
  // `who` says `act` for `seconds` (one tick), then the tick after the end.
  void say(ScriptRunner& runner, Commands& commands, const AgentRef& who, const std::string& act,
           double seconds) {
    start(who, act);
    tick(runner, commands, seconds);
    stop(who);
    tick(runner, commands);
  }
};

class GroupDiscussionRunner : public ::testing::Test {
 protected:
  Scenario scenario = load_scenario_file(kSource + "/scenarios/group_discussion.yaml");
  ScriptRunner runner{scenario, 1};
  RecordingCommands commands;
  Stage stage;
};

TEST_F(GroupDiscussionRunner, PlaysTheSeedsScriptInOrder) {
  const AgentRef ari = AgentRef::ari(), irene = AgentRef::human(11);
  stage.tick(runner, commands);
  EXPECT_EQ(runner.state(), "grouping");
  EXPECT_EQ(commands.log, std::vector<std::string>{"join " + kIrenePerson});

  // 1.6 m from Irene: still grouping; 1.4 m: ARI asks (D6.4 §3.7: closer than 1.5 m).
  stage.obs.world.ari->pose.position = {4.0, 3.6};
  stage.tick(runner, commands);
  EXPECT_EQ(runner.state(), "grouping");
  stage.obs.world.ari->pose.position = {4.0, 3.4};
  stage.tick(runner, commands);
  EXPECT_EQ(runner.state(), "ask_help");
  EXPECT_EQ(commands.log.back(), "say ARI QUESTION:HELP");

  // Irene asks only once ARI's question has finished.
  stage.start(ari, "QUESTION:HELP");
  stage.tick(runner, commands, 2.0);
  EXPECT_EQ(runner.state(), "ask_help");
  stage.stop(ari);
  stage.tick(runner, commands);
  EXPECT_EQ(runner.state(), "ask_time");
  EXPECT_EQ(commands.log.back(), "say human 11 QUESTION:TIME");

  // ARI answers what it heard: Irene's question said is not enough, a transcript near it is.
  stage.start(irene, "QUESTION:TIME");
  stage.tick(runner, commands, 1.5);
  stage.stop(irene);
  stage.tick(runner, commands);
  EXPECT_EQ(runner.state(), "ask_time");
  stage.obs.transcripts = {
      {"voice1", "oh yes what is the lifts", 0.5}};  // two words wrong, one missing
  stage.tick(runner, commands);
  stage.obs.transcripts.clear();
  EXPECT_EQ(commands.log.back(), "say ARI ANSWER:TIME");
  stage.say(runner, commands, ari, "ANSWER:TIME", 1.0);
  EXPECT_EQ(commands.log.back(), "say human 11 GOODBYE");
  stage.say(runner, commands, irene, "GOODBYE", 1.0);
  EXPECT_EQ(runner.state(), "leave");
  const std::vector<std::string> tail(commands.log.end() - 2, commands.log.end());
  EXPECT_EQ(tail, (std::vector<std::string>{"say ARI GOODBYE", "navigate 1.000000"}));

  // Back within 0.5 m of (1, 5): 0.6 m away is not enough, 0.4 m is.
  stage.obs.world.ari->pose.position = {1.6, 5.0};
  stage.tick(runner, commands);
  EXPECT_FALSE(runner.finished());
  stage.obs.world.ari->pose.position = {1.4, 5.0};
  stage.tick(runner, commands);
  ASSERT_TRUE(runner.finished());
  EXPECT_TRUE(runner.outcome()->success);
  EXPECT_EQ(runner.outcome()->reason, "ARI left the group");
  EXPECT_EQ(runner.outcome()->final_state, "leave");
  // The first tick starts the script; then 2 approach ticks, 4 ticks that end an utterance, one
  // that hears and 2 return ticks of 0.05 s each, and 2.0 + 1.5 + 1.0 + 1.0 s of speech.
  EXPECT_NEAR(runner.outcome()->end_time_s, 5.5 + 9 * 0.05, 1e-9);

  std::vector<std::string> visited;
  for (const StateVisit& v : runner.visits()) {
    visited.push_back(v.state);
  }
  EXPECT_EQ(visited, (std::vector<std::string>{"look", "grouping", "ask_help", "ask_time",
                                               "answer_time", "thank_ari", "leave"}));
  ASSERT_EQ(runner.transcript().lines().size(), 4u);
  EXPECT_EQ(runner.transcript().lines()[1].speaker_name, "human 11");

  // Once finished, nothing more happens.
  const size_t commands_sent = commands.log.size();
  stage.tick(runner, commands);
  EXPECT_EQ(commands.log.size(), commands_sent);
}

TEST_F(GroupDiscussionRunner, AnActFinishedBeforeTheStateWasEnteredDoesNotCount) {
  // ARI says QUESTION:HELP on its own before it reaches the group; the script's own question,
  // asked on arrival, is the one Irene must wait for.
  stage.tick(runner, commands);
  stage.start(AgentRef::ari(), "QUESTION:HELP");
  stage.tick(runner, commands);
  stage.stop(AgentRef::ari());
  stage.tick(runner, commands);
  stage.obs.world.ari->pose.position = {4.0, 3.0};
  stage.tick(runner, commands);
  EXPECT_EQ(runner.state(), "ask_help");
  for (int i = 0; i < 20; ++i) {
    stage.tick(runner, commands);
  }
  EXPECT_EQ(runner.state(), "ask_help");
}

TEST_F(GroupDiscussionRunner, OnlyATranscriptHeardInTheStateAndNearIreneLineCounts) {
  stage.tick(runner, commands);
  stage.obs.transcripts = {
      {"voice1", "hello yes what is the time", 0.5}};  // heard before ARI asked: too early
  stage.obs.world.ari->pose.position = {4.0, 3.0};
  stage.tick(runner, commands);
  stage.obs.transcripts.clear();
  stage.say(runner, commands, AgentRef::ari(), "QUESTION:HELP", 0.05);
  ASSERT_EQ(runner.state(), "ask_time");
  // Irene's goodbye, and an empty final, are not the question.
  for (const std::string heard : {"thank you good bye", ""}) {
    stage.obs.transcripts = {{"voice1", heard, 0.5}};
    stage.tick(runner, commands);
    EXPECT_EQ(runner.state(), "ask_time") << heard;
  }
  stage.obs.transcripts = {{"voice1", "what is the time", 0.5}};
  stage.tick(runner, commands);
  EXPECT_EQ(runner.state(), "answer_time");
}

TEST_F(GroupDiscussionRunner, WordsTakenForNoLineMakeAriAskAgain) {
  const AgentRef ari = AgentRef::ari(), irene = AgentRef::human(11);
  stage.tick(runner, commands);
  stage.obs.world.ari->pose.position = {4.0, 3.0};
  stage.tick(runner, commands);
  stage.say(runner, commands, ari, "QUESTION:HELP", 0.05);
  ASSERT_EQ(runner.state(), "ask_time");
  // pocketsphinx's reading of her question in a failed run: one word of six shared.
  stage.obs.transcripts = {{"voice1", "oh yes we're a bit that right", 0.5}};
  stage.tick(runner, commands);
  stage.obs.transcripts.clear();
  EXPECT_EQ(runner.state(), "ask_again");
  EXPECT_EQ(commands.log.back(), "say ARI REQUEST:REPEAT");
  // She asks again once ARI has finished, and a transcript of the shorter question is heard.
  stage.tick(runner, commands);
  EXPECT_EQ(commands.log.back(), "say ARI REQUEST:REPEAT");
  stage.say(runner, commands, ari, "REQUEST:REPEAT", 2.0);
  EXPECT_EQ(runner.state(), "ask_time");
  EXPECT_EQ(commands.log.back(), "say human 11 QUESTION:TIME");
  stage.start(irene, "QUESTION:TIME");
  stage.tick(runner, commands, 1.0);
  stage.stop(irene);
  stage.obs.transcripts = {{"voice1", "what is the time", 0.5}};
  stage.tick(runner, commands);
  EXPECT_EQ(runner.state(), "answer_time");
  EXPECT_EQ(commands.log.back(), "say ARI ANSWER:TIME");
}

TEST(HeardLines, ATranscriptIsTheActOfTheNearestHumanLine) {
  const Scenario scenario = load_scenario_file(kSource + "/scenarios/group_discussion.yaml");
  const HeardLines lines(scenario.script);
  EXPECT_EQ(lines.texts(), (std::vector<std::string>{"Hello. Yes. What is the time?",
                                                     "What is the time?", "Thank you. Good bye."}));
  EXPECT_EQ(lines.act_of("Hello, yes: what is the time?"), "QUESTION:TIME");
  EXPECT_EQ(lines.act_of("thank you good bye"), "GOODBYE");
  // 3 of 6 words shared with a 6-word transcript: cosine 0.5, the least that counts.
  EXPECT_EQ(lines.act_of("brilliant what a big the time"), "QUESTION:TIME");
  EXPECT_EQ(lines.act_of("brilliant what a big dog time"), std::nullopt);
  // ARI's lines are not the humans'.
  EXPECT_EQ(lines.act_of("it is fourteen thirty"), std::nullopt);
  EXPECT_TRUE(lines.has_act("QUESTION:*"));
  EXPECT_FALSE(lines.has_act("ANSWER:TIME"));
}

TEST_F(GroupDiscussionRunner, AriSpeechThroughTtsTakesTheScriptsAct) {
  // dialogue_node voices /tts goals with the act `tts`: the script's own act is recognised by the
  // text it asked ARI to say.
  stage.tick(runner, commands);
  stage.obs.world.ari->pose.position = {4.0, 3.0};
  stage.tick(runner, commands);
  ASSERT_EQ(runner.state(), "ask_help");
  stage.start(AgentRef::ari(), "tts", "Hello, I am ARI. Can I help you?");
  stage.tick(runner, commands);
  stage.stop(AgentRef::ari());
  stage.tick(runner, commands);
  EXPECT_EQ(runner.state(), "ask_time");
  ASSERT_EQ(runner.transcript().lines().size(), 1u);
  EXPECT_EQ(runner.transcript().lines()[0].act, "QUESTION:HELP");
}

TEST_F(GroupDiscussionRunner, NavigationFailureEndsTheRunAsAFailure) {
  stage.tick(runner, commands);
  stage.obs.navigation = {NavigationState::kFailed, "target lost"};
  stage.tick(runner, commands);
  ASSERT_TRUE(runner.finished());
  EXPECT_FALSE(runner.outcome()->success);
  EXPECT_EQ(runner.outcome()->reason, "ARI could not join the group");
}

TEST_F(GroupDiscussionRunner, TheTimeLimitEndsTheRunNamingTheState) {
  stage.tick(runner, commands);
  stage.tick(runner, commands, 119.0);
  EXPECT_FALSE(runner.finished());
  stage.tick(runner, commands, 1.0);
  ASSERT_TRUE(runner.finished());
  EXPECT_FALSE(runner.outcome()->success);
  EXPECT_NE(runner.outcome()->reason.find("time limit of 120"), std::string::npos);
  EXPECT_NE(runner.outcome()->reason.find("grouping"), std::string::npos);
  EXPECT_NEAR(runner.outcome()->end_time_s, 120.0, 1e-9);
}

TEST_F(GroupDiscussionRunner, AbortAndInterruptEndTheRunFromOutsideAtTheLastTick) {
  stage.tick(runner, commands);
  stage.tick(runner, commands, 12.0);  // 12.05 s after the first tick, still grouping
  ScriptRunner interrupted{scenario, 1};
  interrupted.interrupt("SIGINT");  // before its first tick
  runner.abort("no /sim/world_state for 10 s (world_node gone?) while in state grouping");
  runner.interrupt("SIGINT");  // too late: the run has ended
  ASSERT_TRUE(runner.finished());
  EXPECT_FALSE(runner.outcome()->success);
  EXPECT_FALSE(runner.outcome()->interrupted);
  EXPECT_EQ(runner.outcome()->final_state, "grouping");
  EXPECT_NEAR(runner.outcome()->end_time_s, 12.0, 1e-9);
  EXPECT_EQ(runner.outcome()->reason,
            "no /sim/world_state for 10 s (world_node gone?) while in state grouping");
  ASSERT_TRUE(interrupted.finished());
  EXPECT_TRUE(interrupted.outcome()->interrupted);
  EXPECT_EQ(interrupted.outcome()->final_state, "");
  EXPECT_EQ(interrupted.outcome()->reason, "SIGINT");
}

TEST_F(GroupDiscussionRunner, ARefusedCommandEndsTheRunNamingStateAndAction) {
  commands.refuse = "join";
  stage.tick(runner, commands);
  ASSERT_TRUE(runner.finished());
  EXPECT_FALSE(runner.outcome()->success);
  EXPECT_EQ(runner.outcome()->reason,
            "state grouping: join_group (of human 11) refused: no human with id 99");
}

TEST_F(GroupDiscussionRunner, JoiningAHumanNotPerceivedAsAnyPersonFailsTheNavigation) {
  // Perception has matched Paul only: navigation cannot be told whom to join and is made to fail,
  // as for a goal it rejects, so that the script's navigation_failed transition applies; the run
  // goes on.
  stage.obs.world.humans[1].name = "Irene";
  stage.obs.person_ids.erase(11);
  stage.tick(runner, commands);
  EXPECT_EQ(runner.state(), "grouping");
  EXPECT_EQ(commands.log,
            std::vector<std::string>{"fail: human 11 (Irene) is not perceived as any person yet"});
  EXPECT_FALSE(runner.finished());
}

// A scenario from inline text, for the conditions D6.4's script does not use.
Scenario inline_scenario(const std::string& script) {
  const std::string text = "world: " + kSource + "/worlds/room_6x6.yaml\nseed: 2\n" +
                           "ari: {position: [1, 5]}\n"
                           "humans: [{id: 10, position: [3, 2]}, {id: 11, position: [4, 2]}]\n"
                           "script:\n" +
                           script;
  return parse_scenario(core::YamlMap::parse(text, "inline.yaml"), kSource + "/scenarios",
                        "inline");
}

TEST(ScriptRunner, TimeElapsedCountsFromEnteringTheState) {
  const Scenario s = inline_scenario(
      "  time_limit: 60\n  start: a\n  states:\n"
      "    - name: a\n      transitions: [{when: [{type: time_elapsed, seconds: 2}], next: b}]\n"
      "    - name: b\n      transitions: [{when: [{type: time_elapsed, seconds: 3}], do: "
      "[{type: stop, success: true}]}]\n");
  ScriptRunner runner(s, 2);
  RecordingCommands commands;
  Stage stage;
  stage.obs.world.time_s = 10.0;  // the run started before the script: times are relative
  int ticks = 0;
  while (!runner.finished() && ticks < 1000) {
    stage.tick(runner, commands, 0.5);
    ++ticks;
  }
  ASSERT_TRUE(runner.finished());
  // a entered at 0 (first tick at 10.5 s), b at 2.0 s, stop at 5.0 s.
  EXPECT_NEAR(runner.visits()[1].enter_s, 2.0, 1e-9);
  EXPECT_NEAR(runner.outcome()->end_time_s, 5.0, 1e-9);
}

TEST(ScriptRunner, HumanGoalReachedWithinTheTolerance) {
  const Scenario s = inline_scenario(
      "  time_limit: 60\n  start: a\n  states:\n"
      "    - name: a\n      enter: [{type: set_goal, who: 10, position: [5, 2]}]\n"
      "      transitions: [{when: [{type: goal_reached, who: 10, tolerance: 0.25}], do: "
      "[{type: stop, success: true}]}]\n");
  ScriptRunner runner(s, 2);
  RecordingCommands commands;
  Stage stage;
  world::HumanSnapshot& paul = stage.obs.world.humans[0];
  paul.goal = core::Pose2{{5.0, 2.0}, 0.0};
  stage.tick(runner, commands);
  EXPECT_EQ(commands.log, std::vector<std::string>{"goal 10 5.000000"});
  paul.pose.position = {4.7, 2.0};  // 0.30 m away
  stage.tick(runner, commands);
  EXPECT_FALSE(runner.finished());
  paul.pose.position = {4.8, 2.0};  // 0.20 m away
  stage.tick(runner, commands);
  EXPECT_TRUE(runner.finished());
}

TEST(ScriptRunner, SetPostureAsksTheWorldToSitAHumanDown) {
  const Scenario s = inline_scenario(
      "  time_limit: 60\n  start: a\n  states:\n"
      "    - name: a\n      enter: [{type: set_posture, who: 10, posture: sitting}]\n"
      "      transitions: [{when: [{type: time_elapsed, seconds: 1}], do: "
      "[{type: set_posture, who: 10, posture: standing}, {type: stop, success: true}]}]\n");
  ScriptRunner runner(s, 2);
  RecordingCommands commands;
  Stage stage;
  while (!runner.finished()) {
    stage.tick(runner, commands, 0.5);
  }
  EXPECT_EQ(commands.log, (std::vector<std::string>{"posture 10 sitting", "posture 10 standing"}));
  EXPECT_EQ(runner.outcome()->success, true);
}

TEST(ScriptRunner, PerceivedGroupNeedsEveryListedMember) {
  const Scenario s = inline_scenario(
      "  time_limit: 60\n  start: a\n  states:\n"
      "    - name: a\n      transitions: [{when: [{type: perceived_group, members: [ari, 11]}], "
      "do: [{type: stop, success: true}]}]\n");
  ScriptRunner runner(s, 2);
  RecordingCommands commands;
  Stage stage;
  stage.obs.perceived_groups = {{"g1", {AgentRef::human(10), AgentRef::human(11)}}};
  stage.tick(runner, commands);
  EXPECT_FALSE(runner.finished());
  stage.obs.perceived_groups.push_back(
      {"g2", {AgentRef::human(11), AgentRef::ari(), AgentRef::human(10)}});
  stage.tick(runner, commands);
  EXPECT_TRUE(runner.finished());
}

// A script of one state that stops once `condition` holds, and Paul (10) and Irene (11) talking
// in group 1 (each test sets who speaks to whom); ARI (id 1) stands apart.
struct TalkingPair {
  explicit TalkingPair(const std::string& condition)
      : scenario(inline_scenario("  time_limit: 60\n  start: a\n  states:\n"
                                 "    - name: a\n      transitions: [{when: [" +
                                 condition + "], do: [{type: stop, success: true}]}]\n")),
        runner(scenario, 2) {
    world::GroupSnapshot group;
    group.id = 1;
    group.members = {10, 11};
    group.converses = true;
    stage.obs.world.groups = {group};
    stage.obs.world.humans[0].group_id = 1;
    stage.obs.world.humans[1].group_id = 1;
    stage.obs.world.ari->id = 1;
  }
  world::GroupSnapshot& group() { return stage.obs.world.groups[0]; }
  // Two ticks: a condition that holds ends the run.
  bool finished_after_ticks() {
    stage.tick(runner, commands);
    stage.tick(runner, commands);
    return runner.finished();
  }

  const Scenario scenario;  // the runner keeps a reference
  ScriptRunner runner;
  RecordingCommands commands;
  Stage stage;
};

TEST(ScriptRunner, FloorFreeWaitsForAPauseInThePersonsGroup) {
  TalkingPair pair("{type: floor_free, person: 10}");
  pair.group().speaker = 11;  // Irene has the floor
  EXPECT_FALSE(pair.finished_after_ticks());
  pair.group().speaker = model::kNoObject;  // a pause
  EXPECT_TRUE(pair.finished_after_ticks());
}

TEST(ScriptRunner, AddressedCountsAMemberSpeakingToAriSinceTheStateBegan) {
  TalkingPair pair("{type: addressed}");
  pair.group().speaker = 10;
  pair.group().addressee = 11;  // Paul talks to Irene
  EXPECT_FALSE(pair.finished_after_ticks());
  pair.group().addressee = 1;  // to ARI, who is not in the group yet
  EXPECT_FALSE(pair.finished_after_ticks());
  pair.group().robot_joining = 1;
  pair.stage.tick(pair.runner, pair.commands);
  pair.group().addressee = 11;  // a moment to ARI is enough
  EXPECT_TRUE(pair.finished_after_ticks());
}

TEST(ScriptRunner, RandomGroupsAreAddedBeforeTheStartState) {
  const Scenario s = inline_scenario(
      "  time_limit: 60\n  start: a\n"
      "  random_groups: [{id: 4, first_human_id: 30, size: [3, 3], centre_min: [2, 2], "
      "centre_max: [3, 3]}]\n"
      "  states: [{name: a, enter: [{type: join_group, person: 30}]}]\n");
  ScriptRunner runner(s, 7);
  RecordingCommands commands;
  Stage stage;
  stage.obs.person_ids[30] = "human30";
  stage.tick(runner, commands);
  EXPECT_EQ(commands.log, (std::vector<std::string>{"add 30", "add 31", "add 32", "group 4 of 3",
                                                    "join human30"}));
}

TEST(ScriptRunner, ActPatterns) {
  EXPECT_TRUE(act_matches("GOODBYE", "GOODBYE"));
  EXPECT_FALSE(act_matches("GOODBYE", "GOODBYE2"));
  EXPECT_TRUE(act_matches("inform*", "inform(location(toilet))"));
  EXPECT_FALSE(act_matches("inform*", "request(location(toilet))"));
  EXPECT_TRUE(act_matches("*", "anything"));
}

// What an hour-long run of `states` (starting at state a) keeps of its visits.
struct VisitRecord {
  std::vector<StateVisit> visits;
  size_t unrecorded{0};
  std::string csv_states;
};

VisitRecord run_for_an_hour(const std::string& states) {
  const Scenario s = inline_scenario("  time_limit: 3600\n  start: a\n  states:\n" + states);
  ScriptRunner runner(s, 2);
  RecordingCommands commands;
  Stage stage;
  while (!runner.finished()) {
    stage.tick(runner, commands, 0.5);
  }
  return {runner.visits(), runner.unrecorded_visits(),
          batch::EpisodeSummary::of("inline", 0, 2, runner, {}).states};
}

// A state that polls by re-entering itself every tick, for an hour of sim time: one visit with
// its count, not 7,200; and a script that alternates between two states keeps only the first
// kMaxRecordedVisits visits and counts the rest (a 30,000 s run once kept 174 MB of them).
TEST(ScriptRunner, LoopingStatesKeepABoundedRecord) {
  const std::string poll = "[{when: [{type: time_elapsed, seconds: 0.1}], next: ";
  const VisitRecord looping =
      run_for_an_hour("    - name: a\n      transitions: " + poll + "a}]\n");
  ASSERT_EQ(looping.visits.size(), 1u);
  EXPECT_EQ(looping.visits[0].entries, 7200u);  // the first entry, then one per tick after it
  EXPECT_EQ(looping.unrecorded, 0u);
  EXPECT_EQ(looping.csv_states, "a*7200=3600.00");

  const VisitRecord alternating =
      run_for_an_hour("    - name: a\n      transitions: " + poll + "b}]\n" +
                      "    - name: b\n      transitions: " + poll + "a}]\n");
  EXPECT_EQ(alternating.visits.size(), ScriptRunner::kMaxRecordedVisits);
  EXPECT_EQ(alternating.unrecorded, 7200u - ScriptRunner::kMaxRecordedVisits);
  EXPECT_LT(alternating.csv_states.size(), 10u * ScriptRunner::kMaxRecordedVisits);
  const std::string tail = ";(6200 more)=3100.00";
  ASSERT_GE(alternating.csv_states.size(), tail.size());
  EXPECT_EQ(alternating.csv_states.substr(alternating.csv_states.size() - tail.size()), tail);
}

TEST(ScriptRunner, TimeLimitIsAtMostADay) {
  try {
    inline_scenario("  time_limit: 86401\n  start: a\n  states:\n    - name: a\n");
    FAIL() << "a time_limit over a day was accepted";
  } catch (const core::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("time_limit"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("(0, 86400]"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace ari_social_sim::scenario
