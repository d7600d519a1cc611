#include "ari_social_sim/world/request_check.hpp"

#include <cmath>
#include <sstream>

#include "ari_social_sim/core/number_text.hpp"

namespace ari_social_sim::world {

void RequestCheck::fail(const std::string& field, const std::string& expectation,
                        const std::string& got) const {
  throw core::RequestError(prefix() + field + ": expected " + expectation + ", got " + got);
}

void RequestCheck::unknown_id(const std::string& field, const std::string& kind,
                              model::ObjectId id) const {
  throw core::RequestError(prefix() + field + ": no " + kind + " with id " + std::to_string(id));
}

void RequestCheck::finite(const std::string& field, double value) const {
  if (!std::isfinite(value)) {
    fail(field, "a finite number", core::number_text(value));
  }
}

void RequestCheck::in_range(const std::string& field, double value, const core::Bounds& bounds,
                            const std::string& unit) const {
  // Bounds::contains lets infinity through an open end; a request's numbers are always finite.
  if (!std::isfinite(value) || !bounds.contains(value)) {
    fail(field, "a finite number " + bounds.describe() + (unit.empty() ? "" : " " + unit),
         core::number_text(value));
  }
}

void RequestCheck::heading(const std::string& field, double theta_rad) const {
  in_range(field, theta_rad, core::between(-core::kMaxHeadingRad, core::kMaxHeadingRad), "rad");
}

void RequestCheck::agent(model::ObjectId id, const core::Pose2& pose) const {
  if (id == model::kNoObject) {
    fail("id", "a positive integer", "0");
  }
  finite("pose.x", pose.position.x());
  finite("pose.y", pose.position.y());
  heading("pose.theta", pose.theta);
}

void RequestCheck::on_floor(const std::string& field, const Eigen::Vector2d& point,
                            const model::WorldDescription& world) const {
  for (int axis = 0; axis < 2; ++axis) {
    const double low = world.origin[axis];
    const double high = world.origin[axis] + world.size[axis];
    const double value = point[axis];
    if (!(std::isfinite(value) && value >= low && value <= high)) {
      fail(field + (axis == 0 ? ".x" : ".y"),
           "a finite number inside the world [" + core::number_text(low) + ", " +
               core::number_text(high) + "]",
           core::number_text(value));
    }
  }
}

void RequestCheck::pose_on_floor(const std::string& field, const core::Pose2& pose,
                                 const model::WorldDescription& world) const {
  on_floor(field, pose.position, world);
  heading(field + ".theta", pose.theta);
}

}  // namespace ari_social_sim::world
