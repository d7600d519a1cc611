#include "ari_social_sim/physics/joint_trajectory.hpp"

#include <algorithm>

#include "ari_social_sim/core/check.hpp"

namespace ari_social_sim::physics {
namespace {

enum class SplineOrder { kLinear, kCubic, kQuintic };

// Coefficients of the polynomial joining (p0, v0, a0) at tau = 0 to (p1, v1, a1) at tau = T.
std::array<double, 6> spline(SplineOrder order, double p0, double v0, double a0, double p1,
                             double v1, double a1, double T) {
  std::array<double, 6> c{p0, 0.0, 0.0, 0.0, 0.0, 0.0};
  if (T <= 0.0) {
    c[0] = p1;
    return c;
  }
  const double T2 = T * T;
  const double T3 = T2 * T;
  switch (order) {
    case SplineOrder::kLinear:
      c[1] = (p1 - p0) / T;
      break;
    case SplineOrder::kCubic:
      c[1] = v0;
      c[2] = (3.0 * (p1 - p0) - (2.0 * v0 + v1) * T) / T2;
      c[3] = (2.0 * (p0 - p1) + (v0 + v1) * T) / T3;
      break;
    case SplineOrder::kQuintic: {
      const double T4 = T3 * T;
      const double T5 = T4 * T;
      c[1] = v0;
      c[2] = 0.5 * a0;
      c[3] = (20.0 * (p1 - p0) - (8.0 * v1 + 12.0 * v0) * T - (3.0 * a0 - a1) * T2) / (2.0 * T3);
      c[4] = (30.0 * (p0 - p1) + (14.0 * v1 + 16.0 * v0) * T + (3.0 * a0 - 2.0 * a1) * T2) /
             (2.0 * T4);
      c[5] = (12.0 * (p1 - p0) - 6.0 * (v1 + v0) * T - (a0 - a1) * T2) / (2.0 * T5);
      break;
    }
  }
  return c;
}

SplineOrder order_of(const TrajectoryPoint& point) {
  if (!point.accelerations.empty()) {
    return SplineOrder::kQuintic;
  }
  return point.velocities.empty() ? SplineOrder::kLinear : SplineOrder::kCubic;
}

double value_or_zero(const std::vector<double>& values, size_t i) {
  return values.empty() ? 0.0 : values[i];
}

}  // namespace

JointSetpoint JointSetpoint::at_rest(const std::vector<double>& positions) {
  return {positions, std::vector<double>(positions.size(), 0.0),
          std::vector<double>(positions.size(), 0.0)};
}

JointTrajectory::JointTrajectory(const JointSetpoint& start, double start_time_s,
                                 double points_origin_s, const std::vector<TrajectoryPoint>& points)
    : start_(start), start_time_s_(start_time_s) {
  const size_t joints = start.positions.size();
  JointSetpoint from = start;
  double from_time = start_time_s;
  final_ = start;
  for (const TrajectoryPoint& point : points) {
    ARI_DCHECK(point.positions.size() == joints);
    const double point_time = points_origin_s + point.time_from_start_s;
    // Waypoints already in the past are passed over, except the last, which becomes a step.
    if (point_time <= start_time_s && &point != &points.back()) {
      continue;
    }
    Segment segment;
    segment.start_s = from_time;
    segment.duration_s = std::max(0.0, point_time - from_time);
    const SplineOrder order = order_of(point);
    for (size_t j = 0; j < joints; ++j) {
      segment.coefficients.push_back(
          spline(order, from.positions[j], from.velocities[j], from.accelerations[j],
                 point.positions[j], value_or_zero(point.velocities, j),
                 value_or_zero(point.accelerations, j), segment.duration_s));
    }
    segments_.push_back(segment);
    from = {point.positions, point.velocities, point.accelerations};
    from.velocities.resize(joints, 0.0);
    from.accelerations.resize(joints, 0.0);
    from_time = std::max(point_time, start_time_s);
  }
  final_ = JointSetpoint::at_rest(from.positions);
  end_time_s_ = from_time;
}

JointTrajectory JointTrajectory::hold(const JointSetpoint& state, double time_s) {
  return JointTrajectory(JointSetpoint::at_rest(state.positions), time_s, time_s, {});
}

JointSetpoint JointTrajectory::sample(double time_s) const {
  if (segments_.empty() || time_s < start_time_s_) {
    return segments_.empty() ? final_ : start_;
  }
  if (time_s >= end_time_s_) {
    return final_;
  }
  // Segments are few (a handful of waypoints); a linear scan is the fastest search here.
  const auto segment_it =
      std::find_if(segments_.begin(), segments_.end(),
                   [time_s](const Segment& s) { return time_s < s.start_s + s.duration_s; });
  const Segment& segment = segment_it == segments_.end() ? segments_.back() : *segment_it;
  const double tau = std::clamp(time_s - segment.start_s, 0.0, segment.duration_s);
  JointSetpoint out;
  const size_t joints = segment.coefficients.size();
  out.positions.resize(joints);
  out.velocities.resize(joints);
  out.accelerations.resize(joints);
  for (size_t j = 0; j < joints; ++j) {
    const std::array<double, 6>& c = segment.coefficients[j];
    out.positions[j] =
        c[0] + tau * (c[1] + tau * (c[2] + tau * (c[3] + tau * (c[4] + tau * c[5]))));
    out.velocities[j] =
        c[1] + tau * (2.0 * c[2] + tau * (3.0 * c[3] + tau * (4.0 * c[4] + tau * 5.0 * c[5])));
    out.accelerations[j] =
        2.0 * c[2] + tau * (6.0 * c[3] + tau * (12.0 * c[4] + tau * 20.0 * c[5]));
  }
  return out;
}

}  // namespace ari_social_sim::physics
