#pragma once

#include <map>
#include <string>
#include <vector>

#include "ari_social_sim/scenario/agent_ref.hpp"
#include "ari_social_sim/world/world_snapshot.hpp"

namespace ari_social_sim::scenario {

/// One utterance of the run, as the world played it.
struct TranscriptLine {
  AgentRef speaker;
  std::string speaker_name;  // `ARI`, the human's name, or `human N` when it has none
  std::string act;
  std::string text;
  double start_s{0.0};
  double end_s{-1.0};            // sim time the act finished or was cut off; < 0 while it plays
  double words_per_minute{0.0};  // word k was said at start_s + k * 60 / words_per_minute

  bool finished() const { return end_s >= 0.0; }
};

/// Everything said in a run, in order of starting, built from successive world snapshots: an
/// utterance starts when its speaker speaks with a new start time and finishes when the speaker
/// falls silent, starts another act, or leaves the world. Snapshots must come every step (or at
/// least faster than one word), as /sim/world_state and the batch tool provide them.
class Transcript {
 public:
  /// Records what started and finished since the previous snapshot; returns the indexes of the
  /// lines that finished in this one.
  std::vector<size_t> observe(const world::WorldSnapshot& world);

  const std::vector<TranscriptLine>& lines() const { return lines_; }
  /// Gives a line the act its author meant: ARI's text-to-speech plays text only, labelled `tts`
  /// in the world, while the script knows which act it asked for.
  void relabel(size_t line, const std::string& act) { lines_.at(line).act = act; }

 private:
  struct Playing {
    double start_s;
    size_t line;
  };
  void hear(const AgentRef& speaker, const std::string& name, const world::SpeechSnapshot& speech,
            double now_s, std::map<AgentRef, Playing>& still_playing);

  std::vector<TranscriptLine> lines_;
  std::map<AgentRef, Playing> playing_;
  std::vector<size_t> finished_now_;
};

}  // namespace ari_social_sim::scenario
