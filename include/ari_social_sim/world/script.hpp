#pragma once

#include "ari_social_sim/world/object.hpp"

namespace ari_social_sim::world {

/// Controls objects of the simulation (D6.4 §3.2): runs after all objects and sensors each step.
class Script {
 public:
  virtual ~Script() = default;
  virtual void step(const StepContext& context) = 0;
};

/// A background process (D6.4 §3.2): runs last in each step, after the scripts; reads the world.
class Process {
 public:
  virtual ~Process() = default;
  virtual void step(const Simulation& simulation, const StepContext& context) = 0;
};

}  // namespace ari_social_sim::world
