#pragma once

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "ari_social_sim/core/pose2.hpp"
#include "ari_social_sim/model/object_id.hpp"

class b2Body;

namespace ari_social_sim::world {

class Simulation;
class Object;

/// What a component sees of the step it runs in.
struct StepContext {
  Simulation& simulation;
  double time_s;  // sim time at the start of the step
  double dt_s;    // step length
};

/// When a component runs within Simulation::step (D6.4 §3.2): generators before the physics,
/// sensors after it.
enum class ComponentPhase { kGenerator, kSensor };

/// A modular behaviour or sense attached to an Object (D6.4 §3.2): navigation, gaze, speech, maps.
class Component {
 public:
  virtual ~Component() = default;
  virtual ComponentPhase phase() const = 0;
  virtual void step(Object& owner, const StepContext& context) = 0;
};

enum class ObjectKind { kStatic, kHuman, kAri };

/// A physical entity with a Box2D body and a list of components (D6.4 §3.2). Poses and velocities
/// are cached from the body after each physics step, so readers never touch Box2D.
class Object {
 public:
  Object(model::ObjectId id, ObjectKind kind) : id_(id), kind_(kind) {}
  virtual ~Object() = default;
  Object(const Object&) = delete;
  Object& operator=(const Object&) = delete;

  model::ObjectId id() const { return id_; }
  ObjectKind kind() const { return kind_; }
  b2Body* body() { return body_; }
  const b2Body* body() const { return body_; }
  void attach_body(b2Body* body) { body_ = body; }

  /// Pose of the object's reference point in the map frame (base_footprint for ARI).
  const core::Pose2& pose() const { return pose_; }
  /// Centre of the body's footprint (m, map frame): what social forces and gaze aim at.
  virtual Eigen::Vector2d centre() const { return pose_.position; }
  /// Linear velocity (m/s, map frame) and angular velocity (rad/s) over the last step.
  const Eigen::Vector2d& velocity() const { return velocity_; }
  double angular_velocity() const { return angular_velocity_; }

  /// Adds a component; returns it for the caller to keep a typed pointer.
  template <class C>
  C& add_component(std::unique_ptr<C> component) {
    C& ref = *component;
    components_.push_back(std::move(component));
    return ref;
  }
  void step_components(ComponentPhase phase, const StepContext& context);

  /// Writes the motion planned for this step into the body (after the generator components).
  virtual void apply_motion(const StepContext& context) {}
  /// Reads the body's pose and velocity back after the physics step.
  virtual void sync_from_body(double dt_s);

 protected:
  core::Pose2 pose_;
  Eigen::Vector2d velocity_{Eigen::Vector2d::Zero()};
  double angular_velocity_{0.0};

 private:
  model::ObjectId id_;
  ObjectKind kind_;
  b2Body* body_{nullptr};
  std::vector<std::unique_ptr<Component>> components_;
};

}  // namespace ari_social_sim::world
