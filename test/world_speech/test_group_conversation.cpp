#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/yaml_map.hpp"
#include "ari_social_sim/dialogue/small_talk.hpp"
#include "ari_social_sim/world/conversation_metrics.hpp"
#include "ari_social_sim/world/formation_layout.hpp"
#include "ari_social_sim/world/simulation.hpp"
#include "ari_social_sim/world_speech/small_talk_lines.hpp"
#include "scene_builders.hpp"

// Conversation groups (issue 31): turn-taking and gaze against published figures of real
// conversation (docs/world.md "Conversation", the table printed here), ARI as a participant,
// speech from outside taking the floor, and determinism.

namespace ari_social_sim::world {
namespace {

constexpr int kGroupsPerSize = 100;
constexpr double kTalkS = 120.0;

std::shared_ptr<const ConversationLines> lines() {
  static const std::shared_ptr<const ConversationLines> loaded =
      world_speech::SmallTalkLines::load(std::string(ARI_SOURCE_DIR) + "/config");
  return loaded;
}

// A group of `size` standing in its settled places in an 8 m room, talking.
std::unique_ptr<Simulation> talking_group(int size, uint64_t seed,
                                          const ConversationSpec& talk = {}) {
  auto simulation =
      std::make_unique<Simulation>(test::square_room(8.0), SimulationConfig{0.05, seed, 0.05});
  simulation->set_conversation_lines(lines());
  GroupSpec spec;
  spec.id = 1;
  spec.centre = {4.0, 4.0};
  spec.conversation = talk;
  const std::vector<FormationSlot> places = formation_slots(
      GroupNavigation::settled_shape(spec, static_cast<size_t>(size)), static_cast<size_t>(size));
  for (int i = 0; i < size; ++i) {
    HumanSpec human;
    human.id = 10 + static_cast<model::ObjectId>(i);
    human.name = "P" + std::to_string(i);
    human.pose = {places[static_cast<size_t>(i)].position,
                  places[static_cast<size_t>(i)].facing_rad};
    simulation->add_human(human);
    spec.members.push_back(human.id);
  }
  simulation->add_group(spec);
  return simulation;
}

void run_for(Simulation& simulation, double seconds, ConversationMetrics* metrics) {
  const double until_s = simulation.time_s() + seconds;
  while (simulation.time_s() < until_s - 1e-9) {
    simulation.step();
    if (metrics != nullptr) {
      metrics->observe(WorldSnapshot::of(simulation));
    }
  }
}

// Everything said, as one text: speaker, start and words of each finished act.
std::string transcript(const Simulation& simulation) {
  std::string text;
  for (const Human* human : simulation.humans()) {
    for (const SpeechRecord& record : human->speech().history()) {
      text += std::to_string(human->id()) + "@" + std::to_string(record.start_s) + ":" +
              record.content + "\n";
    }
  }
  return text;
}

TEST(GroupConversation, MatchesPublishedFiguresOfRealConversation) {
  ConversationMetrics metrics;
  for (int size : {2, 3, 4}) {
    for (int seed = 1; seed <= kGroupsPerSize; ++seed) {
      auto simulation = talking_group(size, static_cast<uint64_t>(seed));
      run_for(*simulation, kTalkS, &metrics);
    }
  }
  const ConversationSummary summary = metrics.summary();
  std::printf(
      "| transitions | %zu |\n| offset mode | %.0f ms |\n| offset median | %.0f ms |\n"
      "| overlap share | %.2f |\n| listener gaze at speaker | %.2f of the time, %.2f of gaze at "
      "people |\n| speaker gaze at addressee | %.2f of the time, %.2f of gaze at people |\n"
      "| turns per minute | %.1f |\n",
      summary.transition_offsets_s.size(), 1000 * summary.offset_mode_s,
      1000 * summary.offset_median_s, summary.overlap_share, summary.listener_gaze_at_speaker,
      summary.listener_people_gaze_at_speaker, summary.speaker_gaze_at_addressee,
      summary.speaker_people_gaze_at_addressee, summary.turns_per_minute);
  EXPECT_GT(summary.transition_offsets_s.size(), 5000u);
  // Stivers et al. (2009): the mode of the offsets lies in 0-200 ms in all ten languages.
  EXPECT_GE(summary.offset_mode_s, 0.0);
  EXPECT_LE(summary.offset_mode_s, 0.3);
  EXPECT_GE(summary.offset_median_s, 0.0);
  EXPECT_LE(summary.offset_median_s, 0.4);
  // Heldner & Edlund (2010): 40-45 % of speaker changes in overlap; ours is nearer 30 %, the
  // price of keeping Stivers et al.'s mean (docs/world.md).
  EXPECT_GE(summary.overlap_share, 0.25);
  EXPECT_LE(summary.overlap_share, 0.45);
  // Vertegaal et al. (2001): 0.88 of the gaze at people goes to the one listened to, 0.77 to
  // the one spoken to.
  EXPECT_NEAR(summary.listener_people_gaze_at_speaker, 0.88, 0.05);
  EXPECT_NEAR(summary.speaker_people_gaze_at_addressee, 0.77, 0.07);
  EXPECT_GT(summary.turns_per_minute, 8.0);
  EXPECT_LT(summary.turns_per_minute, 30.0);
}

TEST(GroupConversation, SameSeedSameTranscriptAndGaze) {
  auto first = talking_group(3, 7);
  auto second = talking_group(3, 7);
  auto other = talking_group(3, 8);
  std::vector<model::ObjectId> gaze_first;
  std::vector<model::ObjectId> gaze_second;
  std::vector<double> nods_first;
  std::vector<double> nods_second;
  for (int i = 0; i < 1200; ++i) {
    first->step();
    second->step();
    other->step();
    gaze_first.push_back(WorldSnapshot::of(*first).humans[0].gaze.target);
    gaze_second.push_back(WorldSnapshot::of(*second).humans[0].gaze.target);
    nods_first.push_back(WorldSnapshot::of(*first).humans[1].head_pitch_rad);
    nods_second.push_back(WorldSnapshot::of(*second).humans[1].head_pitch_rad);
  }
  EXPECT_EQ(transcript(*first), transcript(*second));
  EXPECT_EQ(gaze_first, gaze_second);
  EXPECT_EQ(nods_first, nods_second);
  EXPECT_GT(*std::max_element(nods_first.begin(), nods_first.end()), 0.0);
  EXPECT_NE(transcript(*first), transcript(*other));
  EXPECT_GT(transcript(*first).size(), 200u);
}

TEST(GroupConversation, ListenersNodAloneOrWithTheirMmHm) {
  constexpr int kGroups = 30;
  int nods = 0;
  int onsets = 0;
  int with_words = 0;
  int by_the_floor_holder = 0;
  double deepest_rad = 0.0;
  for (int seed = 1; seed <= kGroups; ++seed) {
    auto simulation = talking_group(3, static_cast<uint64_t>(seed));
    std::map<model::ObjectId, double> pitch;
    for (double t = 0.0; t < kTalkS; t += 0.05) {
      simulation->step();
      for (const HumanSnapshot& human : WorldSnapshot::of(*simulation).humans) {
        if (human.head_pitch_rad > 0.0 && pitch[human.id] == 0.0) {
          ++onsets;
          const bool speaking = human.speech.is_speaking;
          with_words += speaking && human.speech.act == "backchannel()";
          by_the_floor_holder += speaking && human.speech.act != "backchannel()";
        }
        pitch[human.id] = human.head_pitch_rad;
        deepest_rad = std::max(deepest_rad, human.head_pitch_rad);
      }
    }
    nods += static_cast<int>(simulation->find_conversation(1)->nods());
  }
  const double alone = 1.0 - static_cast<double>(with_words) / onsets;
  const double per_listener_minute = nods / (kGroups * 3.0 * kTalkS / 60.0);
  std::printf(
      "[ measured ] %d nods (%d onsets seen), %.2f without words, %.1f per member-minute, "
      "deepest %.2f rad\n",
      nods, onsets, alone, per_listener_minute, deepest_rad);
  // Knight (2009): 72 of 116 backchannel nods came without words.
  EXPECT_NEAR(alone, 0.62, 0.08);
  EXPECT_GE(onsets, nods * 9 / 10);  // a nod replaced by the next before it shows is rare
  EXPECT_EQ(by_the_floor_holder, 0);
  EXPECT_LE(deepest_rad, 0.24);
  EXPECT_GT(deepest_rad, 0.15);
  EXPECT_GT(per_listener_minute, 1.0);
}

TEST(GroupConversation, NodsLeaveTheTalkAsItWas) {
  ConversationSpec still;
  still.nod_probability = 0.0;
  still.nod_with_backchannel_probability = 0.0;
  auto nodding = talking_group(3, 4);
  auto not_nodding = talking_group(3, 4, still);
  double pitch_sum = 0.0;
  for (int i = 0; i < 1200; ++i) {
    nodding->step();
    not_nodding->step();
    for (const HumanSnapshot& human : WorldSnapshot::of(*not_nodding).humans) {
      pitch_sum += human.head_pitch_rad;
    }
  }
  EXPECT_EQ(transcript(*nodding), transcript(*not_nodding));
  EXPECT_GT(nodding->find_conversation(1)->nods(), 0u);
  EXPECT_EQ(not_nodding->find_conversation(1)->nods(), 0u);
  EXPECT_EQ(pitch_sum, 0.0);
}

TEST(GroupConversation, SilentWithoutLinesOrWhenSwitchedOff) {
  auto switched_off = talking_group(3, 1);
  switched_off->set_group_conversation(1, false);
  auto without_lines = talking_group(3, 1);
  without_lines->set_conversation_lines(nullptr);
  run_for(*switched_off, 30.0, nullptr);
  run_for(*without_lines, 30.0, nullptr);
  EXPECT_EQ(transcript(*switched_off), "");
  EXPECT_EQ(transcript(*without_lines), "");
  EXPECT_THROW(switched_off->set_group_conversation(9, true), core::RequestError);
}

TEST(GroupConversation, SpeechFromOutsideTakesTheFloor) {
  // A scripted line (/sim/say) makes whoever else had started speaking drop out.
  int dropped = 0;
  int scripted = 0;
  for (uint64_t seed = 1; seed <= 20; ++seed) {
    auto simulation = talking_group(3, seed);
    run_for(*simulation, 20.0, nullptr);
    simulation->say(11, "QUESTION:TIME", "What is the time please");
    run_for(*simulation, 0.1, nullptr);
    const WorldSnapshot state = WorldSnapshot::of(*simulation);
    for (const HumanSnapshot& human : state.humans) {
      dropped +=
          human.id != 11 && human.speech.is_speaking && human.speech.act != "backchannel()" ? 0 : 1;
    }
    scripted += state.groups[0].speaker == 11 ? 1 : 0;
  }
  EXPECT_EQ(scripted, 20);
  EXPECT_EQ(dropped, 60);
}

TEST(GroupConversation, AriTakesPartWhenItJoins) {
  int questions = 0;
  int answered = 0;
  double looked_at_ari = 0.0;
  double looked_total = 0.0;
  for (uint64_t seed = 1; seed <= 10; ++seed) {
    auto simulation = talking_group(3, seed);
    AriSpec ari;
    ari.id = 1;
    ari.pose = {{4.0, 6.0}, -1.5708};
    simulation->add_ari(ari);
    simulation->join_group(1, 1);
    run_for(*simulation, 60.0, nullptr);
    questions += static_cast<int>(simulation->find_conversation(1)->robot_counts().questions);
    // ARI speaks: the members look at it and one of them answers it.
    simulation->say(1, "inform(time)", "It is half past two in the afternoon");
    const double ari_end_s = simulation->time_s() + simulation->ari()->speech().duration_s(
                                                        "It is half past two in the afternoon");
    while (simulation->time_s() < ari_end_s) {
      simulation->step();
      for (const HumanSnapshot& human : WorldSnapshot::of(*simulation).humans) {
        looked_total += 1.0;
        looked_at_ari += human.gaze.target == 1 ? 1.0 : 0.0;
      }
    }
    // The members leave ARI's own dialogue the answer for robot_floor_wait (4 s), then answer.
    run_for(*simulation, 6.0, nullptr);
    for (const Human* human : simulation->humans()) {
      std::vector<SpeechRecord> said(human->speech().history().begin(),
                                     human->speech().history().end());
      said.push_back({human->speech().act(), "", human->speech().start_s()});
      for (const SpeechRecord& record : said) {
        const bool answer = record.act.find("answer(small_talk)") != std::string::npos;
        answered += record.start_s > ari_end_s && answer ? 1 : 0;
      }
    }
  }
  EXPECT_GE(questions, 8);  // members ask ARI from the dialogue domain
  EXPECT_GT(looked_at_ari / looked_total, 0.6);
  EXPECT_GE(answered, 8);
}

// ARI's entry counts as in a pause when no member holds the floor in the first state in which
// the formation takes it in; ARI joining at random moments meets both.
TEST(ConversationMetrics, TellsWhetherAriEnteredInAPause) {
  int in_pause = 0;
  int over_speech = 0;
  for (uint64_t seed = 1; seed <= 12; ++seed) {
    auto simulation = talking_group(3, seed);
    run_for(*simulation, 5.0 + 0.7 * static_cast<double>(seed), nullptr);
    AriSpec ari;
    ari.id = 1;
    ari.pose = {{4.0, 6.0}, -1.5708};
    simulation->add_ari(ari);
    simulation->join_group(1, 1);
    ConversationMetrics metrics;
    int expected = -1;
    while (expected < 0 && simulation->time_s() < 60.0) {
      simulation->step();
      const WorldSnapshot state = WorldSnapshot::of(*simulation);
      metrics.observe(state);
      if (state.groups[0].robot_joining == 1) {
        expected = state.groups[0].speaker == model::kNoObject ? 1 : 0;
      }
    }
    ASSERT_GE(expected, 0) << "seed " << seed << ": ARI never taken in";
    EXPECT_EQ(metrics.summary().robot_entered_in_pause, expected) << "seed " << seed;
    (expected == 1 ? in_pause : over_speech) += 1;
  }
  EXPECT_GT(in_pause, 0);
  EXPECT_GT(over_speech, 0);
  EXPECT_EQ(ConversationMetrics().summary().robot_entered_in_pause, -1);
}

TEST(SmallTalk, RefusesAMissingListAndATopicWithoutTopics) {
  const auto refusal = [](const std::string& text) -> std::string {
    try {
      dialogue::SmallTalk::parse(core::YamlMap::parse(text, "talk.yaml"));
    } catch (const core::ConfigError& e) {
      return e.what();
    }
    return "";
  };
  const std::string lists = "statements: [Hi.]\nquestions: [\"Well?\"]\nbackchannels: [Mm-hm.]\n";
  EXPECT_NE(refusal(lists).find("answers"), std::string::npos) << refusal(lists);
  const std::string topic = lists + "answers: [\"About {object}.\"]\n";
  EXPECT_NE(refusal(topic).find("answers[0]"), std::string::npos) << refusal(topic);
  EXPECT_EQ(refusal(topic + "topics: [the bus]\n"), "");
}

}  // namespace
}  // namespace ari_social_sim::world
