// Direction of arrival in the shipped scenes (docs/audio.md, "Direction of arrival"): the
// localiser (SRP-PHAT on the four raw microphones) on every voiced 64 ms chunk of each shipped
// scenario's episodes, run in process, against where the speakers' mouths truly are. Chunks in
// which ARI speaks are left out (its own voice, 0.4 m from the array, is the loudest then), and so
// are speakers nearer than 1 m or farther than 4 m. One talker: the error to them; two talkers at
// once: the error to the nearer in direction of the two. Prints a Markdown table.
//
// usage: doa_benchmark [EPISODES_PER_SCENARIO]   (default 3)

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "ari_social_sim/audio/chunk_analysis.hpp"
#include "ari_social_sim/audio/sound_localizer.hpp"
#include "ari_social_sim/audio/world_audio.hpp"
#include "ari_social_sim/engine/episode.hpp"

namespace {

using namespace ari_social_sim;

struct Errors {
  std::vector<double> one_talker_deg, two_talkers_deg;
};

double angle_error_deg(double a_rad, double b_rad) {
  return std::abs(std::remainder(a_rad - b_rad, 2.0 * M_PI)) * 180.0 / M_PI;
}

// The error of the localiser on `chunk`, heard while `speakers` spoke, to the nearest of them.
void measure(const audio::ArrayChunk& chunk, const std::vector<audio::SpeakerDirection>& speakers,
             Errors& errors) {
  const std::optional<audio::SoundDirection> found =
      audio::locate_sound(audio::raw_microphones(chunk));
  if (!found) {
    return;
  }
  double error = 180.0;
  for (const audio::SpeakerDirection& speaker : speakers) {
    error = std::min(error, angle_error_deg(found->azimuth_rad, speaker.azimuth_rad));
  }
  (speakers.size() == 1 ? errors.one_talker_deg : errors.two_talkers_deg).push_back(error);
}

void run_episode(const scenario::Scenario& scenario, uint64_t seed,
                 const engine::EpisodeConfig& config,
                 std::shared_ptr<audio::SpeechSynthesizer> synthesizer, Errors& errors) {
  engine::Episode episode(scenario, seed, config);
  const audio::RoomSettings room;
  audio::WorldAudio audio(room, audio::walls_of(scenario.scene.world), seed, synthesizer);
  while (!episode.finished()) {
    episode.step();
    const world::WorldSnapshot& snapshot = episode.snapshot();
    audio.observe(snapshot);
    std::vector<audio::SpeakerDirection> speakers;
    for (const audio::SpeakerDirection& s : audio::speaker_directions(snapshot)) {
      if (s.distance_m >= 1.0 && s.distance_m <= 4.0) {
        speakers.push_back(s);
      }
    }
    const bool ari_speaks = snapshot.ari && snapshot.ari->speech.is_speaking;
    for (const audio::ArrayChunk& chunk : audio.chunks_until(snapshot.time_s)) {
      if (!ari_speaks && (speakers.size() == 1 || speakers.size() == 2) &&
          audio::voice_in(chunk, room)) {
        measure(chunk, speakers, errors);
      }
    }
  }
}

std::string percentiles(std::vector<double> values) {
  if (values.empty()) {
    return "| 0 | - | - |";
  }
  std::sort(values.begin(), values.end());
  const auto at = [&values](double q) {
    return values[static_cast<size_t>(q * static_cast<double>(values.size() - 1))];
  };
  char text[96];
  std::snprintf(text, sizeof text, "| %zu | %.1f | %.1f |", values.size(), at(0.5), at(0.9));
  return text;
}

}  // namespace

int main(int argc, char** argv) {
  const uint64_t episodes = argc > 1 ? std::stoul(argv[1]) : 3;
  const engine::EpisodeConfig config =
      engine::EpisodeConfig::load(std::string(ARI_SOURCE_DIR) + "/config");
  auto synthesizer = std::make_shared<audio::SpeechSynthesizer>();
  std::printf(
      "| scenario | chunks, one talker | median error (deg) | 90th percentile (deg) | chunks, two "
      "talkers | median error (deg) | 90th percentile (deg) "
      "|\n|---|---:|---:|---:|---:|---:|---:|\n");
  Errors all;
  for (const char* name : {"group_discussion", "waiting_room", "join_group", "corridor"}) {
    const scenario::Scenario scenario =
        scenario::load_scenario_file(std::string(ARI_SOURCE_DIR) + "/scenarios/" + name + ".yaml");
    Errors errors;
    for (uint64_t i = 0; i < episodes; ++i) {
      run_episode(scenario, scenario.scene.seed + i, config, synthesizer, errors);
    }
    std::printf("| %s %s %s\n", name, percentiles(errors.one_talker_deg).c_str(),
                percentiles(errors.two_talkers_deg).substr(1).c_str());
    std::fflush(stdout);
    all.one_talker_deg.insert(all.one_talker_deg.end(), errors.one_talker_deg.begin(),
                              errors.one_talker_deg.end());
    all.two_talkers_deg.insert(all.two_talkers_deg.end(), errors.two_talkers_deg.begin(),
                               errors.two_talkers_deg.end());
  }
  std::printf("| all %s %s\n", percentiles(all.one_talker_deg).c_str(),
              percentiles(all.two_talkers_deg).substr(1).c_str());
  return 0;
}
