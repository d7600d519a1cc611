// perception_soak: runs ARI's perception in-process on a crowd for hours of sim time, as fast as
// possible, and prints the size of every per-id container every 10 simulated minutes, with the
// process's heap and resident memory. The sizes must stay flat once the crowd has been around
// for a minute or two: memory follows the people, not the run's length (docs/PERFORMANCE.md,
// "Soak"). The world core keeps every finished utterance (SpeechGenerator::history), which grows
// with the run; the table gives its size and the heap without it.
//
// What runs each 1/30 s step, as the live suite does:
//  - world: N people in a square hall (4 m^2 each), half standing and talking in groups of 2-5,
//    half walking between random goals while talking; ARI in the middle turning on the spot at
//    0.2 rad/s (put back in the middle when walkers have pushed it away), so people keep entering
//    and leaving its views; every `--churn` s a walker leaves the world and a new person (a new
//    world id) walks in, as a busy hall would have;
//  - hri_perception_node: PerceptionPipeline, the detectors-mode CandidateMatcher, and the
//    node's per-id topic bookkeeping (PerIdStore: faces, bodies, voices with id_linger 1 s,
//    persons while known);
//  - group_detection_node: GroupPerception on the perceived bodies;
//  - social_mpc_node: SceneTracker fed with the tracked persons' bodies and the groups;
//  - scenario_node: PersonIdentities matching the script's humans with the persons.
//
// Usage: perception_soak [--hours H] [--humans N] [--seed S] [--errors on|off]
//                        [--person-ids human|random] [--churn SECONDS]

#include <malloc.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/rng.hpp"
#include "ari_social_sim/navigation/scene_tracker.hpp"
#include "ari_social_sim/perception/candidate_matches.hpp"
#include "ari_social_sim/perception/group_candidates.hpp"
#include "ari_social_sim/perception/group_perception.hpp"
#include "ari_social_sim/perception/per_id_store.hpp"
#include "ari_social_sim/perception/perception_pipeline.hpp"
#include "ari_social_sim/scenario/person_identities.hpp"
#include "ari_social_sim/world/map_sensor.hpp"
#include "ari_social_sim/world/simulation.hpp"
#include "ari_social_sim/world/world_snapshot.hpp"
#include "scene_builders.hpp"

namespace {

using namespace ari_social_sim;
using model::ObjectId;

constexpr double kStep_s = 1.0 / 30.0;  // perception's 30 Hz, one frame per world step
constexpr double kAreaPerHuman_m2 = 4.0;
constexpr double kSpawnMargin_m = 0.5;
constexpr double kAriClearance_m = 1.5;   // nobody spawns closer to ARI's base
constexpr double kAriTurnRate_rps = 0.2;  // a full turn every 31 s
constexpr double kAriDrift_m = 0.5;       // ARI pushed farther from the middle is put back
constexpr double kRecentrePeriod_s = 5.0;
constexpr double kIdLinger_s = 1.0;  // hri_perception_node's ~id_linger default
constexpr ObjectId kAriId = 1;
constexpr ObjectId kFirstHumanId = 10;

const std::vector<std::string> kSentences = {
    "Could you tell me which floor the poster session is on please",
    "I think the talk on social robots starts in ten minutes in the big room",
    "Have you seen where they put the coffee this morning",
    "The robot over there keeps turning its head to whoever is speaking",
};

struct Options {
  double hours{2.0};
  size_t humans{200};
  uint64_t seed{7};
  bool errors{true};
  std::string person_ids{"human"};
  double churn_s{10.0};
};

[[noreturn]] void usage(const std::string& problem) {
  std::cerr << "perception_soak: " << problem
            << "\nusage: perception_soak [--hours H] [--humans N] [--seed S] [--errors on|off] "
               "[--person-ids human|random] [--churn SECONDS]\n";
  std::exit(2);
}

Options parse(int argc, char** argv) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (i + 1 >= argc) {
      usage(flag + ": expected a value");
    }
    const std::string value = argv[++i];
    char* end = nullptr;
    if (flag == "--hours") {
      options.hours = std::strtod(value.c_str(), &end);
      if (*end != '\0' || !(options.hours > 0.0)) {
        usage("--hours: expected a number > 0, got " + value);
      }
    } else if (flag == "--humans") {
      const long humans = std::strtol(value.c_str(), &end, 10);
      if (*end != '\0' || humans < 4 || humans > 2000) {
        usage("--humans: expected an integer in [4, 2000], got " + value);
      }
      options.humans = static_cast<size_t>(humans);
    } else if (flag == "--seed") {
      options.seed = std::strtoull(value.c_str(), &end, 10);
      if (*end != '\0' || value.empty()) {
        usage("--seed: expected a non-negative integer, got " + value);
      }
    } else if (flag == "--errors" && (value == "on" || value == "off")) {
      options.errors = value == "on";
    } else if (flag == "--person-ids" && (value == "human" || value == "random")) {
      options.person_ids = value;
    } else if (flag == "--churn") {
      options.churn_s = std::strtod(value.c_str(), &end);
      if (*end != '\0' || !(options.churn_s > 0.0)) {
        usage("--churn: expected seconds > 0, got " + value);
      }
    } else {
      usage("unknown option or value: " + flag + " " + value);
    }
  }
  return options;
}

// kB the world's speech histories hold (SpeechGenerator keeps the last kHistoryLength acts of each
// speaker; see docs/PERFORMANCE.md, "Soak"), and their number: each record's slot and any string
// too long for the small-string buffer, with malloc's 16-byte header per block.
long world_speech_kb(const world::Simulation& simulation, size_t& records) {
  constexpr size_t kSmallString = 15;
  constexpr size_t kMallocHeader = 16;
  size_t bytes = 0;
  records = 0;
  for (const auto& human : simulation.humans()) {
    const std::deque<world::SpeechRecord>& history = human->speech().history();
    records += history.size();
    bytes += history.size() * sizeof(world::SpeechRecord) + kMallocHeader;
    for (const world::SpeechRecord& record : history) {
      for (const std::string* text : {&record.act, &record.content}) {
        bytes += text->capacity() > kSmallString ? text->capacity() + 1 + kMallocHeader : 0;
      }
    }
  }
  return static_cast<long>(bytes / 1024);
}

// kB of resident memory (VmRSS, /proc/self/status), and kB the allocator has handed out and not
// had back (mallinfo2): the heap says what is kept, RSS adds what the allocator keeps mapped.
struct MemoryUse {
  long rss_kb{-1};
  long heap_kb{-1};
};

MemoryUse memory_use() {
  MemoryUse use;
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmRSS:", 0) == 0) {
      use.rss_kb = std::strtol(line.c_str() + 6, nullptr, 10);
    }
  }
  const struct mallinfo2 info = mallinfo2();
  use.heap_kb = static_cast<long>((info.uordblks + info.hblkhd) / 1024);
  return use;
}

// The hall and its people; the churn between steps.
class Crowd {
 public:
  Crowd(const Options& options)
      : side_m_(std::sqrt(options.humans * kAreaPerHuman_m2) + 2.0), rng_(options.seed) {
    world::SimulationConfig config;
    config.step_s = kStep_s;
    config.seed = options.seed;
    simulation_ = std::make_unique<world::Simulation>(world::test::square_room(side_m_), config);
    world::AriSpec ari;
    ari.id = kAriId;
    ari.pose.position = {0.5 * side_m_, 0.5 * side_m_};
    simulation_->add_ari(ari);
    while (simulation_->humans().size() < options.humans) {
      spawn();
    }
    // Half of the people in groups of 2-5 around their mean position, the rest walking.
    std::vector<ObjectId> free;
    for (const auto& human : simulation_->humans()) {
      free.push_back(human->id());
    }
    size_t grouped = 0;
    ObjectId group_id = 1;
    while (grouped + 2 <= options.humans / 2) {
      const size_t size = std::min<size_t>(2 + rng_.uniform_index(4), options.humans / 2 - grouped);
      // The next `size` people nearest a random free one.
      const ObjectId seed_id = free[rng_.uniform_index(free.size())];
      const Eigen::Vector2d at = simulation_->find_human(seed_id)->pose().position;
      std::sort(free.begin(), free.end(), [&](ObjectId a, ObjectId b) {
        return (simulation_->find_human(a)->pose().position - at).squaredNorm() <
               (simulation_->find_human(b)->pose().position - at).squaredNorm();
      });
      world::GroupSpec group;
      group.id = group_id++;
      group.members.assign(free.begin(), free.begin() + static_cast<long>(size));
      free.erase(free.begin(), free.begin() + static_cast<long>(size));
      for (ObjectId member : group.members) {
        group.centre +=
            simulation_->find_human(member)->pose().position / static_cast<double>(size);
      }
      simulation_->add_group(group);
      for (ObjectId member : group.members) {
        world::GazeModel gaze;
        gaze.mean_duration_s = 2.0;
        for (ObjectId other : group.members) {
          if (other != member) {
            gaze.targets.push_back({other, 1.0 / static_cast<double>(size - 1)});
          }
        }
        simulation_->set_human_gaze(member, gaze);
      }
      grouped += size;
    }
    for (ObjectId walker : free) {
      start_walking(walker);
    }
  }

  world::Simulation& simulation() { return *simulation_; }

  // One step of the world with everyone's chatter, goals and ARI's turning; every churn_s a
  // walker leaves and a newcomer walks in.
  void step(double churn_s) {
    const double now_s = simulation_->time_s();
    for (const world::Human* human : simulation_->humans()) {
      if (!human->speech().is_speaking() && rng_.bernoulli(0.01)) {
        simulation_->say(human->id(), "STATEMENT",
                         kSentences[rng_.uniform_index(kSentences.size())]);
      }
      if (human->motion_mode() == world::MotionMode::kNavigation && human->goal() &&
          (human->goal()->position - human->pose().position).norm() <
              human->spec().motion.goal_distance_m) {
        simulation_->set_human_goal(human->id(), random_pose());
      }
    }
    if (now_s >= next_churn_s_) {
      next_churn_s_ = now_s + churn_s;
      replace_a_walker();
    }
    if (now_s >= next_recentre_s_) {
      next_recentre_s_ = now_s + kRecentrePeriod_s;
      recentre_ari();
    }
    simulation_->command_ari_twist(0.0, kAriTurnRate_rps);
    simulation_->step();
  }

  uint64_t replaced() const { return replaced_; }

 private:
  core::Pose2 random_pose() {
    core::Pose2 pose;
    pose.position = {rng_.uniform(kSpawnMargin_m, side_m_ - kSpawnMargin_m),
                     rng_.uniform(kSpawnMargin_m, side_m_ - kSpawnMargin_m)};
    pose.theta = rng_.uniform(-M_PI, M_PI);
    return pose;
  }

  // A new person at a free random place away from ARI, under the next unused id.
  ObjectId spawn() {
    const Eigen::Vector2d centre(0.5 * side_m_, 0.5 * side_m_);
    while (true) {
      world::HumanSpec spec;
      spec.id = simulation_->next_free_id(next_id_);
      spec.pose = random_pose();
      if ((spec.pose.position - centre).norm() < kAriClearance_m) {
        continue;
      }
      try {
        simulation_->add_human(spec);
        next_id_ = spec.id + 1;
        return spec.id;
      } catch (const core::RequestError&) {
        // Overlaps someone: draw another place.
      }
    }
  }

  // Walks between random goals, looking at ARI and at two random people.
  void start_walking(ObjectId walker) {
    simulation_->set_human_goal(walker, random_pose());
    const auto humans = simulation_->humans();
    std::vector<ObjectId> people;
    for (int k = 0; k < 2; ++k) {
      const ObjectId drawn = humans[rng_.uniform_index(humans.size())]->id();
      // Nobody looks at themselves (the world refuses it), nor at one person as two targets.
      if (drawn != walker && std::find(people.begin(), people.end(), drawn) == people.end()) {
        people.push_back(drawn);
      }
    }
    world::GazeModel gaze;
    gaze.mean_duration_s = 2.0;
    const double share = 1.0 / static_cast<double>(people.size() + 1);
    gaze.targets.push_back({kAriId, share});
    for (ObjectId person : people) {
      gaze.targets.push_back({person, share});
    }
    simulation_->set_human_gaze(walker, gaze);
  }

  // Walkers push ARI about (it is a body among theirs); left alone it ends in a corner facing the
  // walls within the hour, seeing nobody. Put back in the middle (when the spot is free), it
  // keeps watching the crowd.
  void recentre_ari() {
    const core::Pose2& pose = simulation_->ari()->pose();
    const Eigen::Vector2d centre(0.5 * side_m_, 0.5 * side_m_);
    if ((pose.position - centre).norm() < kAriDrift_m) {
      return;
    }
    try {
      simulation_->set_pose(kAriId, {centre, pose.theta});
    } catch (const core::RequestError&) {
      // Someone stands there now: try again next time.
    }
  }

  void replace_a_walker() {
    std::vector<ObjectId> walkers;
    for (const auto& human : simulation_->humans()) {
      if (human->motion_mode() == world::MotionMode::kNavigation) {
        walkers.push_back(human->id());
      }
    }
    if (walkers.empty()) {
      return;
    }
    simulation_->remove_human(walkers[rng_.uniform_index(walkers.size())]);
    start_walking(spawn());
    ++replaced_;
  }

  double side_m_;
  core::Rng rng_;
  std::unique_ptr<world::Simulation> simulation_;
  ObjectId next_id_{kFirstHumanId};
  double next_churn_s_{0.0};
  double next_recentre_s_{0.0};
  uint64_t replaced_{0};
};

void print_header() {
  std::printf(
      "%7s %6s %5s %6s %7s | %5s %5s %5s %4s %5s %5s %6s | %6s | %6s %5s | %4s %4s %4s %4s | "
      "%5s %5s | %5s | %6s %7s %7s %7s %7s\n",
      "sim_min", "wall_s", "world", "left", "ids", "btrk", "ftrk", "voice", "utt", "pers", "pids",
      "engage", "verdct", "pairs", "grps", "tb", "tf", "tv", "tp", "mppl", "mgrp", "ident", "said",
      "said_kB", "heap_kB", "rest_kB", "rss_kB");
}

}  // namespace

int main(int argc, char** argv) {
  const Options options = parse(argc, argv);
  try {
    Crowd crowd(options);
    world::Simulation& simulation = crowd.simulation();

    perception::PerceptionConfig config;
    config.seed = static_cast<unsigned>(options.seed);
    config.errors_enabled = options.errors;
    config.persons.id_style = options.person_ids;
    perception::PerceptionPipeline pipeline(config);
    pipeline.set_sight_map(world::rasterize_static_map(simulation.world(), 0.05));
    perception::CandidateMatcher matcher(pipeline.config().matchers, core::Rng(options.seed + 6));
    perception::GroupPerception group_detection(pipeline.config().groups);
    std::vector<perception::PerceivedGroup> groups;
    // hri_perception_node's per-id publishers, as counts.
    const auto nothing = [](const std::string&) { return '\0'; };
    perception::PerIdStore<char> body_topics(nothing), face_topics(nothing), voice_topics(nothing),
        person_topics(nothing);
    navigation::SceneTracker scene_tracker{navigation::SceneTrackerConfig{}};
    scenario::PersonIdentities identities;

    std::printf(
        "perception_soak: %zu people, seed %llu, error models %s, person ids %s, a walker "
        "replaced every %.0f s, %.1f sim-hours at %.0f Hz\n",
        options.humans, static_cast<unsigned long long>(options.seed),
        options.errors ? "on" : "off", options.person_ids.c_str(), options.churn_s, options.hours,
        1.0 / kStep_s);
    print_header();
    const auto wall_start = std::chrono::steady_clock::now();
    const uint64_t steps = static_cast<uint64_t>(std::llround(options.hours * 3600.0 / kStep_s));
    const uint64_t steps_per_minute = static_cast<uint64_t>(std::llround(60.0 / kStep_s));
    for (uint64_t step = 1; step <= steps; ++step) {
      crowd.step(options.churn_s);
      const world::WorldSnapshot snapshot = world::WorldSnapshot::of(simulation);
      const perception::PerceptionFrame& frame = pipeline.update(snapshot);
      const double now_s = frame.time_s;
      matcher.update(frame);
      for (const perception::PerceivedBody& body : frame.bodies) {
        body_topics.of(body.body_id, now_s);
      }
      for (const perception::PerceivedFace& face : frame.faces) {
        face_topics.of(face.face_id, now_s);
      }
      for (const perception::PerceivedVoice& voice : frame.voices) {
        voice_topics.of(voice.voice_id, now_s);
      }
      for (const perception::PersonReport& person : frame.persons) {
        person_topics.of(person.person_id, now_s);
      }
      body_topics.retire(now_s, kIdLinger_s);
      face_topics.retire(now_s, kIdLinger_s);
      voice_topics.retire(now_s, kIdLinger_s);
      person_topics.retire(now_s, 0.0);
      group_detection.update(perception::group_candidates_of(frame), groups);
      for (const perception::PerceivedBody& body : frame.bodies) {
        scene_tracker.observe_person(body.person_id, now_s, body.X_map_body.position,
                                     body.X_map_body.theta);
      }
      for (const perception::PerceivedGroup& group : groups) {
        scene_tracker.observe_group(group.group_id, now_s, group.members);
      }
      scene_tracker.forget(now_s);
      identities.update(snapshot, scenario::sightings_of(frame));

      const uint64_t minute = step / steps_per_minute;
      const bool report = step % steps_per_minute == 0 &&
                          (minute == 1 || minute == 5 || minute % 10 == 0 || step == steps);
      if (!report) {
        continue;
      }
      const perception::PipelineMemory memory = pipeline.memory();
      const MemoryUse use = memory_use();
      size_t said = 0;
      const long said_kb = world_speech_kb(simulation, said);
      const double wall_s =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
      std::printf(
          "%7.0f %6.0f %5zu %6llu %7llu | %5zu %5zu %5zu %4zu %5zu %5zu %6zu | %6zu | %6zu %5zu | "
          "%4zu %4zu %4zu %4zu | %5zu %5zu | %5zu | %6zu %7ld %7ld %7ld %7ld\n",
          now_s / 60.0, wall_s, simulation.humans().size(),
          static_cast<unsigned long long>(crowd.replaced()),
          static_cast<unsigned long long>(memory.ids_issued), memory.body_tracks,
          memory.face_tracks, memory.voices, memory.utterances, memory.persons, memory.person_ids,
          memory.engagement_samples, matcher.remembered_count(), group_detection.pair_count(),
          group_detection.group_track_count(), body_topics.size(), face_topics.size(),
          voice_topics.size(), person_topics.size(), scene_tracker.person_count(),
          scene_tracker.group_count(), identities.person_ids().size(), said, said_kb, use.heap_kb,
          use.heap_kb - said_kb, use.rss_kb);
      std::fflush(stdout);
    }
  } catch (const core::Error& e) {
    std::cerr << "perception_soak: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
