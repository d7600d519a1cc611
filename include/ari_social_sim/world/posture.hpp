#pragma once

#include <cstdint>

#include "ari_social_sim/core/config_fields.hpp"

namespace ari_social_sim::world {

/// Whether a human stands or sits (on a chair; ROS4HRI's hri_msgs/BodyPosture STANDING, SITTING).
enum class Posture : uint8_t { kStanding = 0, kSitting = 1 };

inline constexpr core::Choice<Posture> kPostures[] = {{Posture::kStanding, "standing"},
                                                      {Posture::kSitting, "sitting"}};

/// The posture's name as files, services and /sim/world_state spell it.
const char* posture_name(Posture posture);

/// s; how long standing up or sitting down takes. The five-times sit-to-stand test's norms for
/// people of 60 to 89 (docs/references.md, Bohannon 2006) give 1.1-1.5 s a movement done as fast as
/// possible; an unhurried one in a waiting room takes a little longer.
constexpr double kPostureChangeS = 1.7;
/// m; how far in front of the seat's centre a person stands once up (and starts from to sit down):
/// a seat's depth, 0.45 m, clears a chair as deep (0.225 m) and a body circle of 0.2 m.
constexpr double kSeatToFeetM = 0.45;

/// A posture and how far the change into it has got. The 2D position of a seated person is the
/// seat's centre (where the pelvis rests); standing up carries it kSeatToFeetM forward over the
/// feet, sitting down carries it back, at an even speed over kPostureChangeS.
struct PostureState {
  /// The posture the human is in or changing into.
  Posture posture{Posture::kStanding};
  /// 0..1: how much of the change into `posture` is done; 1: settled.
  double progress{1.0};

  /// 0: standing upright, 1: seated; in between while standing up or sitting down (linear in time).
  double seated_fraction() const;
  /// True only when standing and settled: the one state in which a human walks.
  bool is_standing() const { return posture == Posture::kStanding && progress >= 1.0; }
  bool is_changing() const { return progress < 1.0; }
  /// The posture the body shows, as a posture recogniser would name it: sitting while more than
  /// half seated (the hips nearer the seat than their standing height), standing otherwise.
  Posture apparent() const {
    return seated_fraction() > 0.5 ? Posture::kSitting : Posture::kStanding;
  }

  /// Starts the change into `target`; a change under way turns back from where it got to. Nothing
  /// when already in or changing into `target`.
  void change_to(Posture target);
  /// Advances a change under way by `dt_s`; returns the body's speed (m/s) along its heading over
  /// the step: + while standing up (forward over the feet), - while sitting down, 0 otherwise.
  double advance(double dt_s);
};

}  // namespace ari_social_sim::world
