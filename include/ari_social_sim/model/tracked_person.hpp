#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "ari_social_sim/core/pose2.hpp"

namespace ari_social_sim::model {

/// A person ROS4HRI perception tracks (/humans/persons/tracked) and the body matched to them
/// (/humans/persons/<id>/body_id), which is empty while there is none: the person is only heard,
/// only their face is seen, or the match is still pending.
struct TrackedPerson {
  std::string person_id;
  std::string body_id;
};

/// Where perception last placed a body (its body_<id> frame) and when. The pose is in the frame
/// the caller asked for; theta is the frame's x axis, which REP-155 points where the body faces.
struct BodyPlacement {
  double stamp_s{0.0};
  core::Pose2 pose;
};

/// Farthest (m, each axis) a pose read from perception or tf may lie from the map origin: a
/// building is a few hundred metres (worlds stop at 1000 m, world_description.hpp), so anything
/// beyond is a broken or rogue publisher, not a place. Such a pose, or a non-finite one, is
/// dropped: filtered, it would turn a person's track (and the markers and plan built on it) into
/// infinities and NaN for as long as the person is perceived.
constexpr double kMaxMapCoordinateM = 1e4;

/// "" if `pose` is finite and within kMaxMapCoordinateM of the map origin, else what is wrong,
/// with the coordinates in %g form ("x = 1e+300 beyond +-10000 m", "theta = nan").
std::string pose_problem(const core::Pose2& pose);

/// "" if a transform (tf: translation, rotation quaternion x y z w) can be taken in: translation
/// within kMaxMapCoordinateM on each axis, rotation finite and not zero. Else what is wrong, in
/// %g form. tf2 itself only refuses NaN: a transform at inf or 1e300 would be kept, and a static
/// one (map -> odom) overwritten for good, since tf2 never forgets a static transform.
std::string transform_problem(const double (&translation)[3], const double (&rotation)[4]);

/// A tracked person at their body's placement.
struct PlacedPerson {
  std::string person_id;
  double stamp_s{0.0};
  core::Pose2 pose;
};

/// Where a body stands, or nothing when it cannot be placed: live, tf has no (recent) transform
/// of its frame; in process, the perception frame holds no such body.
using BodyLocator = std::function<std::optional<BodyPlacement>(const std::string& body_id)>;

/// What perception tells the consumers that act on persons at a moment: who is tracked, in the
/// order reported, and where their bodies stand.
struct TrackedPersons {
  std::vector<TrackedPerson> persons;
  BodyLocator locate_body;
};

/// The tracked persons that the consumers needing a facing direction act on (social navigation,
/// group detection), in the order given, each at their body's placement. Left out: a person
/// without a body, since a person frame has a position but no meaningful orientation (REP-155),
/// and one whose body `locate_body` cannot place or places absurdly (pose_problem).
/// (Takes the persons by value: a caller done with them moves them in, and their ids move on.)
std::vector<PlacedPerson> place_at_bodies(std::vector<TrackedPerson> persons,
                                          const BodyLocator& locate_body);

}  // namespace ari_social_sim::model
