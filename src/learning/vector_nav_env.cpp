#include "ari_social_sim/learning/vector_nav_env.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "ari_social_sim/core/error.hpp"

namespace ari_social_sim::learning {

VectorNavEnv::VectorNavEnv(const std::shared_ptr<const NavEnvSetup>& setup, int num_envs,
                           int threads)
    : final_metrics_(num_envs), threads_(std::clamp(threads, 1, std::max(num_envs, 1))) {
  if (num_envs < 1 || num_envs > kMaxEnvs) {
    throw core::RequestError("learning: num_envs: expected an integer in [1, " +
                             std::to_string(kMaxEnvs) + "], got " + std::to_string(num_envs));
  }
  if (threads < 1 || threads > kMaxThreads) {
    throw core::RequestError("learning: threads: expected an integer in [1, " +
                             std::to_string(kMaxThreads) + "], got " + std::to_string(threads));
  }
  for (int i = 0; i < num_envs; ++i) {
    envs_.push_back(make_env(setup));
    envs_.back()->set_seed_stride(static_cast<uint64_t>(num_envs));
  }
  errors_.resize(threads_);
  for (int t = 1; t < threads_; ++t) {
    workers_.emplace_back(&VectorNavEnv::worker, this, t);
  }
}

VectorNavEnv::~VectorNavEnv() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  start_.notify_all();
  for (std::thread& worker : workers_) {
    worker.join();
  }
}

void VectorNavEnv::reset(std::optional<uint64_t> seed, float* observations) {
  const int size = observation_size();
  for_each_env([&](int i) {
    std::optional<uint64_t> own;
    if (seed) {
      own = *seed + static_cast<uint64_t>(i);
    }
    envs_[i]->reset(own, observations + static_cast<size_t>(i) * size);
  });
}

void VectorNavEnv::step(const float* actions, const VectorStepOutput& out) {
  const int width = action_size();
  for (int i = 0; i < num_envs(); ++i) {
    for (int k = 0; k < width; ++k) {
      const float value = actions[i * width + k];
      if (!std::isfinite(value)) {
        throw core::RequestError("learning: actions[" + std::to_string(i) + ", " +
                                 std::to_string(k) + "] (" + action_name(k) +
                                 "): expected a finite number, got " + std::to_string(value));
      }
    }
  }
  const size_t size = static_cast<size_t>(observation_size());
  for_each_env([&](int i) {
    Env& env = *envs_[i];
    float* observation = out.observations + i * size;
    const NavStepResult result = env.step(actions + i * width, observation);
    out.rewards[i] = result.reward;
    out.terminated[i] = result.terminated;
    out.truncated[i] = result.truncated;
    if (env.done()) {
      std::memcpy(out.final_observations + i * size, observation, size * sizeof(float));
      final_metrics_[i] = env.metrics();
      env.reset(std::nullopt, observation);
    }
  });
}

void VectorNavEnv::for_each_env(const std::function<void(int)>& work) {
  if (threads_ == 1) {
    for (int i = 0; i < num_envs(); ++i) {
      work(i);
    }
    return;
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    work_ = &work;
    running_ = threads_ - 1;
    ++generation_;
    std::fill(errors_.begin(), errors_.end(), nullptr);
  }
  start_.notify_all();
  // The caller's thread takes the first share.
  try {
    for (int i = 0; i < num_envs(); i += threads_) {
      work(i);
    }
  } catch (...) {
    errors_[0] = std::current_exception();
  }
  std::unique_lock<std::mutex> lock(mutex_);
  finished_.wait(lock, [this] { return running_ == 0; });
  work_ = nullptr;
  for (const std::exception_ptr& error : errors_) {
    if (error) {
      std::rethrow_exception(error);
    }
  }
}

void VectorNavEnv::worker(int thread) {
  uint64_t seen = 0;
  for (;;) {
    const std::function<void(int)>* work = nullptr;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      start_.wait(lock, [&] { return stopping_ || generation_ != seen; });
      if (stopping_) {
        return;
      }
      seen = generation_;
      work = work_;
    }
    try {
      for (int i = thread; i < num_envs(); i += threads_) {
        (*work)(i);
      }
    } catch (...) {
      errors_[thread] = std::current_exception();
    }
    {
      std::lock_guard<std::mutex> lock(mutex_);
      --running_;
    }
    finished_.notify_one();
  }
}

}  // namespace ari_social_sim::learning
