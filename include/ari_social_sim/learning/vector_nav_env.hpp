#pragma once

#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "ari_social_sim/learning/nav_env.hpp"

namespace ari_social_sim::learning {

/// Where a vector environment writes a step's results: arrays of num_envs rows, owned by the
/// caller (numpy arrays in Python).
struct VectorStepOutput {
  float* observations{nullptr};        // num_envs x observation_size
  double* rewards{nullptr};            // num_envs
  bool* terminated{nullptr};           // num_envs
  bool* truncated{nullptr};            // num_envs
  float* final_observations{nullptr};  // num_envs x observation_size: an ended episode's last
};

/// N navigation environments of one task (make_env) stepped together. Environment i's episodes are
/// seeds seed + i, seed + i + N, seed + i + 2N, ... An episode that ends is reset at once (in the
/// same step): its last observation goes to final_observations, its metrics stay in
/// final_metrics(i), and the row of observations is the next episode's first. With threads > 1 the
/// environments are split among that many threads (the caller's one of them); each environment only
/// ever depends on its own seed, so results are the same for any thread count.
class VectorNavEnv {
 public:
  /// Bounds of a vector environment: each environment holds a world, perception and a map (about
  /// 2 MB), and more threads than cores only wait on each other.
  static constexpr int kMaxEnvs = 4096;
  static constexpr int kMaxThreads = 64;

  /// Throws core::RequestError naming num_envs or threads outside [1, kMaxEnvs] or
  /// [1, kMaxThreads].
  VectorNavEnv(const std::shared_ptr<const NavEnvSetup>& setup, int num_envs, int threads);
  ~VectorNavEnv();
  VectorNavEnv(const VectorNavEnv&) = delete;
  VectorNavEnv& operator=(const VectorNavEnv&) = delete;

  int num_envs() const { return static_cast<int>(envs_.size()); }
  int observation_size() const { return envs_.front()->observation_size(); }
  int action_size() const { return envs_.front()->action_size(); }
  const Env& env(int i) const { return *envs_[i]; }
  /// The metrics of environment i's last ended episode.
  const NavMetrics& final_metrics(int i) const { return final_metrics_[i]; }

  /// Resets every environment; with a seed, environment i starts at seed + i.
  void reset(std::optional<uint64_t> seed, float* observations);
  /// `actions` is num_envs x action_size(). Throws core::RequestError naming the environment and
  /// element of the first value that is not finite, before any environment steps.
  void step(const float* actions, const VectorStepOutput& out);

 private:
  /// Runs work(i) for every environment, split among the threads.
  void for_each_env(const std::function<void(int)>& work);
  void worker(int thread);

  std::vector<std::unique_ptr<Env>> envs_;
  std::vector<NavMetrics> final_metrics_;
  int threads_{1};

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable start_;
  std::condition_variable finished_;
  const std::function<void(int)>* work_{nullptr};
  uint64_t generation_{0};
  int running_{0};
  bool stopping_{false};
  std::vector<std::exception_ptr> errors_;
};

}  // namespace ari_social_sim::learning
