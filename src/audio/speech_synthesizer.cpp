#include "ari_social_sim/audio/speech_synthesizer.hpp"

#include <espeak-ng/speak_lib.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>

#include "ari_social_sim/audio/resampler.hpp"
#include "ari_social_sim/core/control_characters.hpp"
#include "ari_social_sim/core/error.hpp"

namespace ari_social_sim::audio {
namespace {

// What the child process hands back: espeak-ng's samples and word starts at its own rate.
struct RawSpeech {
  std::vector<int16_t> samples;
  std::vector<int32_t> word_starts;
};

RawSpeech* g_child_speech = nullptr;  // the child's only synthesis; espeak's callback is a C one

int collect(short* wave, int count, espeak_EVENT* events) {
  if (wave != nullptr) {
    g_child_speech->samples.insert(g_child_speech->samples.end(), wave, wave + count);
  }
  for (; events != nullptr && events->type != espeakEVENT_LIST_TERMINATED; ++events) {
    if (events->type == espeakEVENT_WORD) {
      g_child_speech->word_starts.push_back(events->sample);
    }
  }
  return 0;
}

bool write_all(int fd, const void* data, size_t bytes) {
  const char* at = static_cast<const char*>(data);
  while (bytes > 0) {
    const ssize_t written = write(fd, at, bytes);
    if (written < 0 && errno == EINTR) {
      continue;
    }
    if (written <= 0) {
      return false;
    }
    at += written;
    bytes -= static_cast<size_t>(written);
  }
  return true;
}

bool read_all(int fd, void* data, size_t bytes) {
  char* at = static_cast<char*>(data);
  while (bytes > 0) {
    const ssize_t got = read(fd, at, bytes);
    if (got < 0 && errno == EINTR) {
      continue;
    }
    if (got <= 0) {
      return false;
    }
    at += got;
    bytes -= static_cast<size_t>(got);
  }
  return true;
}

// In the child: synthesise and write [rate, sample count, word count, samples, word starts].
[[noreturn]] void synthesize_in_child(int fd, const std::string& text, const Voice& voice) {
  RawSpeech speech;
  g_child_speech = &speech;
  const int32_t rate = espeak_Initialize(AUDIO_OUTPUT_SYNCHRONOUS, 0, nullptr, 0);
  const std::string name = "en-us+" + voice.variant;
  if (rate <= 0 || espeak_SetVoiceByName(name.c_str()) != EE_OK) {
    _exit(3);
  }
  espeak_SetSynthCallback(collect);
  espeak_SetParameter(espeakRATE, voice.rate_wpm, 0);
  espeak_SetParameter(espeakPITCH, voice.pitch, 0);
  espeak_SetParameter(espeakRANGE, voice.pitch_range, 0);
  espeak_Synth(text.c_str(), text.size() + 1, 0, POS_CHARACTER, 0, espeakCHARS_UTF8, nullptr,
               nullptr);
  const uint64_t counts[2] = {speech.samples.size(), speech.word_starts.size()};
  const bool sent =
      write_all(fd, &rate, sizeof(rate)) && write_all(fd, counts, sizeof(counts)) &&
      write_all(fd, speech.samples.data(), speech.samples.size() * sizeof(int16_t)) &&
      write_all(fd, speech.word_starts.data(), speech.word_starts.size() * sizeof(int32_t));
  _exit(sent ? 0 : 4);
}

// In the parent: the child's answer, or nothing when it could not be read whole.
bool read_child(int fd, int32_t& rate, RawSpeech& speech) {
  uint64_t counts[2] = {0, 0};
  if (!read_all(fd, &rate, sizeof(rate)) || !read_all(fd, counts, sizeof(counts))) {
    return false;
  }
  speech.samples.resize(counts[0]);
  speech.word_starts.resize(counts[1]);
  return read_all(fd, speech.samples.data(), counts[0] * sizeof(int16_t)) &&
         read_all(fd, speech.word_starts.data(), counts[1] * sizeof(int32_t));
}

Synthesis synthesize_fresh(const std::string& text, const Voice& voice) {
  int pipe_fds[2];
  if (pipe(pipe_fds) != 0) {
    throw core::Error("speech synthesis: no pipe: " + std::string(std::strerror(errno)));
  }
  const pid_t child = fork();
  if (child == 0) {
    close(pipe_fds[0]);
    synthesize_in_child(pipe_fds[1], text, voice);
  }
  close(pipe_fds[1]);
  int32_t rate = 0;
  RawSpeech speech;
  const bool read = child > 0 && read_child(pipe_fds[0], rate, speech);
  close(pipe_fds[0]);
  int status = 0;
  while (child > 0 && waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  if (!read || !WIFEXITED(status) || WEXITSTATUS(status) != 0 || rate <= 0) {
    throw core::Error("speech synthesis: espeak-ng failed on voice " + voice.key() +
                      " (is espeak-ng-data installed? scripts/install_deps.sh)");
  }
  std::vector<float> samples(speech.samples.size());
  for (size_t i = 0; i < samples.size(); ++i) {
    samples[i] = speech.samples[i] / 32768.0f;
  }
  Synthesis synthesis;
  synthesis.samples = resample(samples, rate, kSampleRateHz);
  for (const int32_t start : speech.word_starts) {
    synthesis.word_starts.push_back(
        static_cast<size_t>(static_cast<int64_t>(start) * kSampleRateHz / rate));
  }
  return synthesis;
}

}  // namespace

std::string speakable_text(const std::string& text, bool* truncated) {
  core::check_no_control_characters("speech synthesis: text", text, "\t\n");
  *truncated = text.size() > kMaxUtteranceBytes;
  if (!*truncated) {
    return text;
  }
  const size_t cut = text.find_last_of(" \t\n", kMaxUtteranceBytes);
  return text.substr(0, cut == std::string::npos ? kMaxUtteranceBytes : cut);
}

std::shared_ptr<const Synthesis> SpeechSynthesizer::synthesize(const std::string& text,
                                                               const Voice& voice) {
  check_voice(voice);
  bool truncated = false;
  const std::string spoken = speakable_text(text, &truncated);
  const std::string key = voice.key() + "|" + spoken;
  std::lock_guard<std::mutex> lock(mutex_);
  const auto cached = cache_.find(key);
  if (cached != cache_.end()) {
    return cached->second;
  }
  auto synthesis = std::make_shared<Synthesis>();
  if (spoken.find_first_not_of(" \t\n") != std::string::npos) {
    *synthesis = synthesize_fresh(spoken, voice);
  }
  synthesis->truncated = truncated;
  cache_[key] = synthesis;
  return synthesis;
}

size_t SpeechSynthesizer::cached() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return cache_.size();
}

}  // namespace ari_social_sim::audio
