#include "ari_social_sim/scenario/transcript.hpp"

namespace ari_social_sim::scenario {

void Transcript::hear(const AgentRef& speaker, const std::string& name,
                      const world::SpeechSnapshot& speech, double now_s,
                      std::map<AgentRef, Playing>& still_playing) {
  const auto playing = playing_.find(speaker);
  const bool same_act =
      playing != playing_.end() && speech.is_speaking && playing->second.start_s == speech.start_s;
  if (same_act) {
    still_playing.insert(*playing);
    return;
  }
  if (playing != playing_.end()) {
    lines_[playing->second.line].end_s = now_s;
    finished_now_.push_back(playing->second.line);
  }
  if (speech.is_speaking) {
    lines_.push_back(
        {speaker, name, speech.act, speech.content, speech.start_s, -1.0, speech.words_per_minute});
    still_playing[speaker] = {speech.start_s, lines_.size() - 1};
  }
}

std::vector<size_t> Transcript::observe(const world::WorldSnapshot& world) {
  finished_now_.clear();
  std::map<AgentRef, Playing> still_playing;
  if (world.ari) {
    hear(AgentRef::ari(), "ARI", world.ari->speech, world.time_s, still_playing);
  }
  for (const world::HumanSnapshot& human : world.humans) {
    const std::string name = human.name.empty() ? "human " + std::to_string(human.id) : human.name;
    hear(AgentRef::human(human.id), name, human.speech, world.time_s, still_playing);
  }
  // Speakers no longer in the world stop where they were.
  for (const auto& [speaker, playing] : playing_) {
    if (still_playing.count(speaker) == 0 && !lines_[playing.line].finished()) {
      lines_[playing.line].end_s = world.time_s;
      finished_now_.push_back(playing.line);
    }
  }
  playing_ = std::move(still_playing);
  return finished_now_;
}

}  // namespace ari_social_sim::scenario
