#include "ari_social_sim/dataset/episode_audio.hpp"

#include <sndfile.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/world/speech_generator.hpp"

namespace ari_social_sim::dataset {
namespace {

std::string seconds(double s) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", s);
  return text;
}

std::string speaker_label(const scenario::TranscriptLine& line) {
  std::string name = line.speaker_name;
  std::replace(name.begin(), name.end(), ' ', '_');
  return name;
}

// When a line ended: its end, or the recording's end for one still going.
double end_of(const scenario::TranscriptLine& line, double end_s) {
  return line.finished() ? line.end_s : end_s;
}

void write_text(const std::string& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  if (!out) {
    throw core::Error(path + ": cannot be written");
  }
}

// A word as CTM lists it: without the punctuation around it ("ARI." is "ARI", "14:30" stays).
std::string bare(const std::string& word) {
  const auto is_mark = [](char c) { return std::ispunct(static_cast<unsigned char>(c)) != 0; };
  const auto first = std::find_if_not(word.begin(), word.end(), is_mark);
  const auto last = std::find_if_not(word.rbegin(), word.rend(), is_mark).base();
  return first < last ? std::string(first, last) : word;
}

std::string file_name(const std::string& stem) {
  const size_t slash = stem.find_last_of('/');
  return slash == std::string::npos ? stem : stem.substr(slash + 1);
}

}  // namespace

std::string rttm_of(const std::vector<scenario::TranscriptLine>& lines,
                    const std::string& recording, double end_s) {
  std::string rttm;
  for (const scenario::TranscriptLine& line : lines) {
    const double duration = end_of(line, end_s) - line.start_s;
    if (duration > 0.0) {
      rttm += "SPEAKER " + recording + " 1 " + seconds(line.start_s) + " " + seconds(duration) +
              " <NA> <NA> " + speaker_label(line) + " <NA> <NA>\n";
    }
  }
  return rttm;
}

std::string ctm_of(const std::vector<scenario::TranscriptLine>& lines, const std::string& recording,
                   double end_s) {
  std::string ctm;
  for (const scenario::TranscriptLine& line : lines) {
    if (line.words_per_minute <= 0.0) {
      continue;
    }
    const std::vector<std::string> words = world::spoken_words(line.text);
    const double word_s = 60.0 / line.words_per_minute;
    const double line_end = end_of(line, end_s);
    for (size_t k = 0; k < words.size(); ++k) {
      const double start = line.start_s + static_cast<double>(k) * word_s;
      const double duration = std::min(start + word_s, line_end) - start;
      if (duration > 0.0) {
        ctm += recording + " 1 " + seconds(start) + " " + seconds(duration) + " " + bare(words[k]) +
               "\n";
      }
    }
  }
  return ctm;
}

EpisodeAudio::EpisodeAudio(const std::string& stem, const world::Scene& scene, uint64_t seed,
                           const audio::RoomSettings& room,
                           std::shared_ptr<audio::SpeechSynthesizer> synthesizer)
    : stem_(stem),
      recording_(file_name(stem)),
      audio_(room, audio::walls_of(scene.world), seed, std::move(synthesizer)) {
  SF_INFO format{};
  format.samplerate = audio::kSampleRateHz;
  format.channels = model::kArrayChannels;
  format.format = SF_FORMAT_WAV | SF_FORMAT_PCM_16;
  wav_ = sf_open((stem_ + ".wav").c_str(), SFM_WRITE, &format);
  if (wav_ == nullptr) {
    throw core::Error(stem_ + ".wav: cannot be written (" + sf_strerror(nullptr) + ")");
  }
  directions_.open(stem_ + "_directions.csv");
  directions_ << "time_s,human_id,azimuth_deg,distance_m\n";
  if (!directions_) {
    throw core::Error(stem_ + "_directions.csv: cannot be written");
  }
}

EpisodeAudio::~EpisodeAudio() {
  if (wav_ != nullptr) {
    sf_close(wav_);
  }
}

void EpisodeAudio::observe(const world::WorldSnapshot& snapshot) {
  audio_.observe(snapshot);
  transcript_.observe(snapshot);
  last_time_s_ = snapshot.time_s;
  for (const audio::ArrayChunk& chunk : audio_.chunks_until(snapshot.time_s)) {
    write(chunk, snapshot);
  }
}

void EpisodeAudio::write(const audio::ArrayChunk& chunk, const world::WorldSnapshot& snapshot) {
  const size_t samples = chunk.channels[0].size();
  interleaved_.resize(samples * model::kArrayChannels);
  for (size_t i = 0; i < samples; ++i) {
    for (size_t c = 0; c < model::kArrayChannels; ++c) {
      interleaved_[i * model::kArrayChannels + c] = chunk.channels[c][i];
    }
  }
  if (sf_writef_short(wav_, interleaved_.data(), static_cast<sf_count_t>(samples)) !=
      static_cast<sf_count_t>(samples)) {
    throw core::Error(stem_ + ".wav: writing failed (" + sf_strerror(wav_) + ")");
  }
  const double time_s = static_cast<double>(chunk.first_sample) / audio::kSampleRateHz;
  for (const audio::SpeakerDirection& d : audio::speaker_directions(snapshot)) {
    directions_ << seconds(time_s) << ',' << d.human_id << ','
                << seconds(d.azimuth_rad * 180.0 / M_PI) << ',' << seconds(d.distance_m) << '\n';
  }
}

void EpisodeAudio::finish() {
  sf_close(wav_);
  wav_ = nullptr;
  write_text(stem_ + ".rttm", rttm_of(transcript_.lines(), recording_, last_time_s_));
  write_text(stem_ + ".ctm", ctm_of(transcript_.lines(), recording_, last_time_s_));
  directions_.close();
  if (!directions_) {
    throw core::Error(stem_ + "_directions.csv: cannot be written");
  }
}

std::string EpisodeAudio::stem_of(const std::string& dir, const std::string& name, uint64_t seed) {
  return dir + "/audio/" + name + "_" + std::to_string(seed);
}

std::vector<std::string> EpisodeAudio::files_of(const std::string& stem) {
  return {stem + ".wav", stem + ".rttm", stem + ".ctm", stem + "_directions.csv"};
}

}  // namespace ari_social_sim::dataset
