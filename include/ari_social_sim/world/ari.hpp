#pragma once

#include <Eigen/Core>
#include <cmath>
#include <optional>

#include "ari_social_sim/core/config_fields.hpp"
#include "ari_social_sim/core/number_text.hpp"
#include "ari_social_sim/model/ari_footprint.hpp"
#include "ari_social_sim/model/ari_limits.hpp"
#include "ari_social_sim/world/differential_drive.hpp"
#include "ari_social_sim/world/head_pan_controller.hpp"
#include "ari_social_sim/world/map_sensor.hpp"
#include "ari_social_sim/world/object.hpp"
#include "ari_social_sim/world/speech_generator.hpp"

namespace ari_social_sim::world {

struct AriSpec {
  model::ObjectId id{1};
  core::Pose2 pose;  // base_footprint in the map frame
  double head_pan_rad{0.0};
  double words_per_minute{150.0};
  model::AriLimits limits;
  model::AriFootprint footprint;

  /// ARI as a scene file's `ari` entry writes it (config_fields.hpp). Its limits and footprint
  /// are the real robot's, not a scene's to change; validate() checks them too.
  template <class V>
  void visit(V& v) {
    v.field("id", id, "ARI's object id, unique in the world", core::positive());
    pose.visit(v);
    v.field("head_pan", head_pan_rad, "rad, head_1_joint at the start, within its limit");
    v.rule("head_pan", std::abs(head_pan_rad) <= limits.head_pan_limit_rad,
           "a number in [-" + core::number_text(limits.head_pan_limit_rad) + ", " +
               core::number_text(limits.head_pan_limit_rad) + "]",
           core::number_text(head_pan_rad));
    v.field("words_per_minute", words_per_minute, "speaking rate", core::positive());
  }

  /// Throws core::RequestError naming the first field outside what visit, the limits' and the
  /// footprint's visits allow (id 0, a non-finite pose, a head pan beyond the joint limit, ...).
  /// Whether the pose lies on the floor is the simulation's check (Simulation::add_ari).
  void validate() const;
};

/// ARI's 2D body (D6.4 §3.5): base_footprint pose, body orientation and head pan, driven by twist
/// and pan commands within ARI's limits; speaks with the same SpeechGenerator as humans.
class Ari : public Object {
 public:
  /// `map_resolution_m` is the cell size of ARI's MapSensor.
  Ari(const AriSpec& spec, double map_resolution_m);

  const AriSpec& spec() const { return spec_; }
  Eigen::Vector2d centre() const override {
    return pose_.transform(spec_.footprint.centre_local());
  }

  DifferentialDrive& drive() { return *drive_; }
  const DifferentialDrive& drive() const { return *drive_; }
  HeadPanController& head() { return *head_; }
  const HeadPanController& head() const { return *head_; }
  SpeechGenerator& speech() { return *speech_; }
  const SpeechGenerator& speech() const { return *speech_; }
  const MapSensor& map_sensor() const { return *map_sensor_; }

  /// 3D mode: ARI's base is simulated elsewhere (ari_physics_node). From now on each step moves
  /// the 2D body onto this pose (map frame) and reports this twist, instead of driving it.
  /// Expects finite numbers: requests are checked by Simulation::follow_ari.
  void follow(const core::Pose2& pose, double linear_mps, double angular_rps);
  bool is_following() const { return followed_.has_value(); }
  /// The base's twist: the drive's, or the followed one in 3D mode.
  double linear_mps() const { return followed_ ? followed_linear_mps_ : drive_->linear_mps(); }
  double angular_rps() const { return followed_ ? followed_angular_rps_ : drive_->angular_rps(); }

  void apply_motion(const StepContext& context) override;

 private:
  AriSpec spec_;
  DifferentialDrive* drive_;
  HeadPanController* head_;
  SpeechGenerator* speech_;
  MapSensor* map_sensor_;
  std::optional<core::Pose2> followed_;
  double followed_linear_mps_{0.0};
  double followed_angular_rps_{0.0};
};

}  // namespace ari_social_sim::world
