#include <benchmark/benchmark.h>
#include <time.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include "ari_social_sim/core/rng.hpp"
#include "ari_social_sim/world/group_navigation.hpp"
#include "ari_social_sim/world/group_report.hpp"
#include "ari_social_sim/world/human.hpp"
#include "ari_social_sim/world/simulation.hpp"
#include "ari_social_sim/world_speech/small_talk_lines.hpp"
#include "scene_builders.hpp"

namespace {

using namespace ari_social_sim;
using model::ObjectId;

constexpr uint64_t kSeed = 7;
constexpr double kStepS = 0.05;
// 30 s of sim time: group members walk to their o-space (they start near it) and settle (the
// group model settles within ~30 s), walkers spread out, and everyone has started speaking.
constexpr int kWarmUpSteps = 600;
// Floor per person (m^2): a busy hall where people still walk freely.
constexpr double kAreaPerHumanM2 = 4.0;
// Spawn margin (m) from the walls, and margin of the o-space centres from the walls.
constexpr double kSpawnMarginM = 0.5;
constexpr double kGroupMarginM = 1.5;
// A group's o-space counts as formed when every member stands within this of its circle.
constexpr double kFormedToleranceM = 0.3;
constexpr size_t kGazeTargetsPerWalker = 3;

// Utterances of 10 to 20 words, as a person in a hall might say.
const std::vector<std::string> kSentences = {
    "I think the talk on social robots starts in ten minutes in the big room",
    "Have you seen where they put the coffee and the small cakes this morning",
    "My flight was delayed for two hours so I only arrived at the hotel after midnight and slept "
    "badly",
    "The robot over there keeps turning its head to whoever is speaking",
    "We should try the new restaurant near the station before the conference dinner on Thursday "
    "evening",
    "Could you tell me which floor the poster session is on please",
    "Last year the demo failed because the network went down during the very first minute of the "
    "show",
    "I would rather walk back to the hotel than wait for the shuttle bus in this rain",
};

// Keeps the crowd busy during the measured steps: whoever is silent starts a new sentence, and a
// walker that reached its goal gets another one. Runs after every Simulation::step, within the
// timed loop, so the speech and goal updates are part of what is timed. It changes the world
// through its requests, as any client of the world does.
class CrowdActivity {
 public:
  /// `groups_left_alone`: group members are not made to speak (their groups converse on their
  /// own); only the others are.
  CrowdActivity(double side_m, uint64_t seed, bool groups_left_alone)
      : side_m_(side_m), rng_(seed), groups_left_alone_(groups_left_alone) {}

  void step(world::Simulation& simulation) {
    for (const world::Human* human : simulation.humans()) {
      const bool left_alone = groups_left_alone_ && human->group_id() != model::kNoObject;
      if (!left_alone && !human->speech().is_speaking()) {
        simulation.say(human->id(), "STATEMENT", kSentences[rng_.uniform_index(kSentences.size())]);
      }
      if (human->motion_mode() == world::MotionMode::kNavigation && human->goal() &&
          (human->goal()->position - human->pose().position).norm() <
              human->spec().motion.goal_distance_m) {
        simulation.set_human_goal(human->id(), random_pose());
      }
    }
  }

  core::Pose2 random_pose() {
    core::Pose2 pose;
    pose.position = {rng_.uniform(kSpawnMarginM, side_m_ - kSpawnMarginM),
                     rng_.uniform(kSpawnMarginM, side_m_ - kSpawnMarginM)};
    pose.theta = rng_.uniform(-M_PI, M_PI);
    return pose;
  }

 private:
  double side_m_;
  core::Rng rng_;
  bool groups_left_alone_;
};

// Sizes of 2 to 5 adding up to `total` (>= 2), never leaving a single person over.
std::vector<size_t> group_sizes(size_t total, core::Rng& rng) {
  std::vector<size_t> sizes;
  size_t remaining = total;
  while (remaining >= 2) {
    size_t size = std::min<size_t>(remaining, 2 + rng.uniform_index(4));
    if (remaining - size == 1) {
      size = size == 5 ? 4 : size + 1;
    }
    sizes.push_back(size);
    remaining -= size;
  }
  return sizes;
}

// O-space centres on a jittered grid over the room, cells picked at random: centres at least
// ~0.7 cell apart (4.9 m cells for 500 humans), so neighbouring formations do not merge.
std::vector<Eigen::Vector2d> group_centres(size_t count, double side_m, core::Rng& rng) {
  const size_t per_side = static_cast<size_t>(std::ceil(std::sqrt(static_cast<double>(count))));
  const double cell_m = (side_m - 2.0 * kGroupMarginM) / static_cast<double>(per_side);
  std::vector<size_t> cells(per_side * per_side);
  for (size_t i = 0; i < cells.size(); ++i) {
    cells[i] = i;
  }
  for (size_t i = cells.size(); i > 1; --i) {
    std::swap(cells[i - 1], cells[rng.uniform_index(i)]);
  }
  std::vector<Eigen::Vector2d> centres;
  for (size_t k = 0; k < count; ++k) {
    const double x = kGroupMarginM + (static_cast<double>(cells[k] % per_side) + 0.5) * cell_m;
    const double y = kGroupMarginM + (static_cast<double>(cells[k] / per_side) + 0.5) * cell_m;
    centres.emplace_back(x + rng.uniform(-0.15, 0.15) * cell_m,
                         y + rng.uniform(-0.15, 0.15) * cell_m);
  }
  return centres;
}

world::GazeModel gaze_at(const std::vector<ObjectId>& targets) {
  world::GazeModel model;
  model.mean_duration_s = 2.0;
  for (ObjectId id : targets) {
    model.targets.push_back({id, 1.0 / static_cast<double>(targets.size())});
  }
  return model;
}

// The benchmark scene and what keeps it busy; one step of it is one world step and the activity.
struct Crowd {
  std::unique_ptr<world::Simulation> simulation;
  CrowdActivity activity;

  void step() {
    simulation->step();
    activity.step(*simulation);
  }
};

// How the benchmark crowd talks.
enum class Talk {
  kNonStop,     // everyone without pause, made to by CrowdActivity; groups silent on their own
  kConversing,  // everyone stands in a group that converses (docs/world.md section 12)
  kGroupsMadeToTalk,  // the same groups, conversation off, made to talk as kNonStop: before
};

// The benchmark scene: `count` humans in a square room at kAreaPerHumanM2 each (side
// sqrt(4 N) + 2 m). With kNonStop, half of them stand in groups of 2-5 (the humans nearest each
// o-space centre) and look at the other members, the rest walk between random goals and look at
// three random people, and everyone talks without pause (CrowdActivity). With kConversing,
// everyone stands in a group of 2-5 and the groups converse with the package's small talk; with
// kGroupsMadeToTalk, the same groups' conversation is off (ConversationSpec::enabled false) and
// CrowdActivity makes everyone talk without pause, as the world's groups talked before issue 31.
// Warmed up by kWarmUpSteps.
Crowd make_crowd(size_t count, uint64_t seed, Talk talk) {
  const double side_m = std::sqrt(static_cast<double>(count) * kAreaPerHumanM2) + 2.0;
  world::SimulationConfig config;
  config.step_s = kStepS;
  config.seed = seed;
  auto simulation = std::make_unique<world::Simulation>(world::test::square_room(side_m), config);
  core::Rng rng(seed);
  const std::vector<ObjectId> ids = world::test::add_random_humans(
      *simulation, static_cast<int>(count), side_m, kSpawnMarginM, rng);

  const bool conversing = talk == Talk::kConversing;
  const bool all_in_groups = talk != Talk::kNonStop;
  const bool groups_left_alone = talk == Talk::kConversing;
  if (conversing) {
    simulation->set_conversation_lines(
        world_speech::SmallTalkLines::load(std::string(ARI_SOURCE_DIR) + "/config"));
  }
  // Groups: each takes the still unassigned humans nearest its centre.
  const std::vector<size_t> sizes = group_sizes(all_in_groups ? count : count / 2, rng);
  const std::vector<Eigen::Vector2d> centres = group_centres(sizes.size(), side_m, rng);
  std::vector<ObjectId> free_ids = ids;
  ObjectId group_id = 1;
  for (size_t g = 0; g < sizes.size(); ++g) {
    const Eigen::Vector2d& centre = centres[g];
    auto distance_sq = [&](ObjectId id) {
      return (simulation->find_human(id)->pose().position - centre).squaredNorm();
    };
    std::partial_sort(free_ids.begin(), free_ids.begin() + static_cast<long>(sizes[g]),
                      free_ids.end(),
                      [&](ObjectId a, ObjectId b) { return distance_sq(a) < distance_sq(b); });
    world::GroupSpec spec;
    spec.id = group_id++;
    spec.members.assign(free_ids.begin(), free_ids.begin() + static_cast<long>(sizes[g]));
    spec.centre = centre;
    spec.conversation.enabled = conversing;
    free_ids.erase(free_ids.begin(), free_ids.begin() + static_cast<long>(sizes[g]));
    for (ObjectId member : spec.members) {
      std::vector<ObjectId> others;
      std::copy_if(spec.members.begin(), spec.members.end(), std::back_inserter(others),
                   [member](ObjectId id) { return id != member; });
      simulation->set_human_gaze(member, gaze_at(others));
    }
    simulation->add_group(spec);
  }

  // Walkers: a random goal each and three random other people to look at.
  Crowd crowd{std::move(simulation), CrowdActivity(side_m, seed + 1, groups_left_alone)};
  for (ObjectId id : free_ids) {
    crowd.simulation->set_human_goal(id, crowd.activity.random_pose());
    std::vector<ObjectId> targets;
    while (targets.size() < kGazeTargetsPerWalker) {
      const ObjectId target = ids[rng.uniform_index(ids.size())];
      if (target != id && std::find(targets.begin(), targets.end(), target) == targets.end()) {
        targets.push_back(target);
      }
    }
    crowd.simulation->set_human_gaze(id, gaze_at(targets));
  }

  for (int i = 0; i < kWarmUpSteps; ++i) {
    crowd.step();
  }
  return crowd;
}

// CPU time (s) of the calling thread.
double thread_cpu_s() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

double formed_group_share(const world::Simulation& simulation) {
  size_t formed = 0;
  for (const world::GroupNavigation* group : simulation.groups()) {
    if (world::GroupReport::of(simulation, *group).max_distance_to_circle_m() < kFormedToleranceM) {
      ++formed;
    }
  }
  return static_cast<double>(formed) / static_cast<double>(simulation.groups().size());
}

// One Simulation::step of 0.05 s (navigation, gaze, speech, physics, group scripts) and the
// CrowdActivity after it. The scene is warmed up once and then keeps running (a Simulation cannot
// be copied to restore it); after the warm-up it is in a steady state (formed groups, walkers,
// constant talk), so consecutive steps cost alike. Items = steps.
void measure_steps(benchmark::State& state, Talk talk) {
  const size_t count = static_cast<size_t>(state.range(0));
  Crowd crowd = make_crowd(count, kSeed, talk);
  const double formed_at_start = formed_group_share(*crowd.simulation);
  const double start_s = thread_cpu_s();
  for (auto _ : state) {
    crowd.step();
  }
  // The counters come from this thread's CPU time, as Google Benchmark's CPU column does: other
  // work on the core (the machine is shared) does not inflate them. Plain values, not Benchmark
  // rate counters, so that they print without a "/s" unit.
  const double step_cpu_s = (thread_cpu_s() - start_s) / static_cast<double>(state.iterations());
  state.SetItemsProcessed(state.iterations());
  state.counters["us_per_step"] = 1e6 * step_cpu_s;
  state.counters["realtime_factor"] = kStepS / step_cpu_s;
  state.counters["human_steps_per_s"] = static_cast<double>(count) / step_cpu_s;
  state.counters["ns_per_human_step"] = 1e9 * step_cpu_s / static_cast<double>(count);
  state.counters["groups_formed"] = formed_at_start;
  state.counters["groups"] = static_cast<double>(crowd.simulation->groups().size());
}

void BM_WorldStep(benchmark::State& state) {
  measure_steps(state, Talk::kNonStop);
}
BENCHMARK(BM_WorldStep)
    ->ArgName("humans")
    ->Arg(10)
    ->Arg(50)
    ->Arg(200)
    ->Arg(500)
    ->Unit(benchmark::kMicrosecond);

// Everyone in a conversation group (issue 31): the turn-taking, the conversation gaze and the
// small talk on top of the world step.
void BM_WorldStepConversing(benchmark::State& state) {
  measure_steps(state, Talk::kConversing);
}
BENCHMARK(BM_WorldStepConversing)->ArgName("humans")->Arg(200)->Unit(benchmark::kMicrosecond);

// The same scene with every group's conversation off and everyone made to talk without pause, as
// before issue 31: what BM_WorldStepConversing costs on top of it.
void BM_WorldStepGroupsMadeToTalk(benchmark::State& state) {
  measure_steps(state, Talk::kGroupsMadeToTalk);
}
BENCHMARK(BM_WorldStepGroupsMadeToTalk)->ArgName("humans")->Arg(200)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
