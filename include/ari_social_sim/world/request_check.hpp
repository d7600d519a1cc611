#pragma once

#include <Eigen/Core>
#include <string>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/pose2.hpp"
#include "ari_social_sim/core/yaml_map.hpp"
#include "ari_social_sim/model/world_description.hpp"

namespace ari_social_sim::world {

/// Checks the numbers of one request against a running simulation before anything changes, so a
/// refused request leaves the world as it was. Every failed check throws core::RequestError
///   `<request>: <field>: expected <expectation>, got <value>`,
/// e.g. `set_goal: goal.x: expected a finite number inside the world [-0.2, 12.2], got nan`, or
/// for an id that names nothing of its kind `<request>: <field>: no <kind> with id <id>`.
/// Requests are named after world_node's services (spawn_human, set_goal, ...), which the
/// in-process engine mirrors; a check without a request name (a spec's own validate()) leaves the
/// prefix out, and `valid(spec)` adds it.
class RequestCheck {
 public:
  RequestCheck() = default;
  explicit RequestCheck(std::string request) : request_(std::move(request)) {}

  /// Any finite number.
  void finite(const std::string& field, double value) const;
  /// A finite number within `bounds`; `unit` (may be empty) follows the interval in the message.
  void in_range(const std::string& field, double value, const core::Bounds& bounds,
                const std::string& unit = "") const;
  /// A finite heading within +-core::kMaxHeadingRad.
  void heading(const std::string& field, double theta_rad) const;
  /// An agent's identity and placement as its spec gives them, before the world is consulted: a
  /// positive `id`, a finite `pose.x` and `pose.y` and a valid `pose.theta`.
  void agent(model::ObjectId id, const core::Pose2& pose) const;
  /// A point on the world's floor: `field.x` and `field.y` each finite and inside its rectangle.
  void on_floor(const std::string& field, const Eigen::Vector2d& point,
                const model::WorldDescription& world) const;
  /// A pose on the floor with a valid heading (`field.x`, `field.y`, `field.theta`).
  void pose_on_floor(const std::string& field, const core::Pose2& pose,
                     const model::WorldDescription& world) const;
  /// Runs `spec.validate()` and names this request in front of its refusal.
  template <class Spec>
  void valid(const Spec& spec) const {
    try {
      spec.validate();
    } catch (const core::RequestError& e) {
      throw core::RequestError(prefix() + e.what());
    }
  }
  /// Throws the refusal for `field`.
  [[noreturn]] void fail(const std::string& field, const std::string& expectation,
                         const std::string& got) const;
  /// Throws the refusal for `field` naming no `kind` of the world (`human`, `group`, ...).
  [[noreturn]] void unknown_id(const std::string& field, const std::string& kind,
                               model::ObjectId id) const;

 private:
  std::string prefix() const { return request_.empty() ? "" : request_ + ": "; }

  std::string request_;
};

}  // namespace ari_social_sim::world
