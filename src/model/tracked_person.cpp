#include "ari_social_sim/model/tracked_person.hpp"

#include <cmath>
#include <utility>

#include "ari_social_sim/core/number_text.hpp"

namespace ari_social_sim::model {

std::string pose_problem(const core::Pose2& pose) {
  const std::pair<const char*, double> coordinates[] = {{"x", pose.position.x()},
                                                        {"y", pose.position.y()}};
  for (const auto& [axis, value] : coordinates) {
    if (!(std::abs(value) <= kMaxMapCoordinateM)) {
      return std::string(axis) + " = " + core::number_text(value) + ", expected within +-" +
             core::number_text(kMaxMapCoordinateM) + " m of the map origin";
    }
  }
  if (!std::isfinite(pose.theta)) {
    return "theta = " + core::number_text(pose.theta) + ", expected a finite angle";
  }
  return "";
}

std::string transform_problem(const double (&translation)[3], const double (&rotation)[4]) {
  const char* const axes[] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i) {
    if (!(std::abs(translation[i]) <= kMaxMapCoordinateM)) {
      return std::string("translation ") + axes[i] + " = " + core::number_text(translation[i]) +
             ", expected within +-" + core::number_text(kMaxMapCoordinateM) + " m";
    }
  }
  double norm2 = 0.0;
  for (const double q : rotation) {
    norm2 += q * q;
  }
  // Finite and far from zero: tf2 normalises it (and refuses one far from unit length).
  if (!(std::isfinite(norm2) && norm2 > 1e-6)) {
    return "rotation norm^2 = " + core::number_text(norm2) + ", expected a unit quaternion";
  }
  return "";
}

std::vector<PlacedPerson> place_at_bodies(std::vector<TrackedPerson> persons,
                                          const BodyLocator& locate_body) {
  std::vector<PlacedPerson> placed;
  placed.reserve(persons.size());
  for (TrackedPerson& person : persons) {
    if (person.body_id.empty()) {
      continue;
    }
    const std::optional<BodyPlacement> body = locate_body(person.body_id);
    if (body && std::isfinite(body->stamp_s) && pose_problem(body->pose).empty()) {
      placed.push_back({std::move(person.person_id), body->stamp_s, body->pose});
    }
  }
  return placed;
}

}  // namespace ari_social_sim::model
