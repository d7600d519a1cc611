#include "ari_social_sim/world/group_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/world/simulation.hpp"

namespace ari_social_sim::world {

double GroupReport::max_distance_to_circle_m() const {
  double worst = 0.0;
  for (const MemberPlacement& m : members) {
    worst = std::max(worst, m.distance_to_circle_m);
  }
  return worst;
}

double GroupReport::max_facing_error_rad() const {
  double worst = 0.0;
  for (const MemberPlacement& m : members) {
    worst = std::max(worst, m.facing_error_rad);
  }
  return worst;
}

double GroupReport::min_member_distance_m() const {
  double closest = std::numeric_limits<double>::infinity();
  for (const MemberDistance& d : distances) {
    closest = std::min(closest, d.distance_m);
  }
  return closest;
}

GroupReport GroupReport::of(const Simulation& simulation, const GroupNavigation& group) {
  GroupReport report;
  report.id = group.id();
  report.centre = group.centre();
  report.ospace_radius_m = group.ospace_radius_m();
  for (model::ObjectId id : group.members()) {
    const Human& human = *simulation.find_human(id);
    MemberPlacement m;
    m.id = id;
    m.position = human.pose().position;
    m.orientation_rad = human.pose().theta;
    const Eigen::Vector2d to_centre = report.centre - m.position;
    m.distance_to_circle_m = std::abs(to_centre.norm() - report.ospace_radius_m);
    m.facing_error_rad = std::abs(
        core::angle_difference(std::atan2(to_centre.y(), to_centre.x()), m.orientation_rad));
    report.members.push_back(m);
  }
  for (size_t i = 0; i < report.members.size(); ++i) {
    for (size_t j = i + 1; j < report.members.size(); ++j) {
      report.distances.push_back(
          {report.members[i].id, report.members[j].id,
           (report.members[i].position - report.members[j].position).norm()});
    }
  }
  return report;
}

std::string GroupReport::to_text() const {
  std::string text;
  char line[200];
  std::snprintf(line, sizeof line, "group %u: o-space centre (%.2f, %.2f), radius %.2f m\n", id,
                centre.x(), centre.y(), ospace_radius_m);
  text += line;
  for (const MemberPlacement& m : members) {
    std::snprintf(line, sizeof line,
                  "  human %u at (%.2f, %.2f) heading %6.1f deg: %.2f m off the circle, facing "
                  "the centre within %.1f deg\n",
                  m.id, m.position.x(), m.position.y(), core::rad_to_deg(m.orientation_rad),
                  m.distance_to_circle_m, core::rad_to_deg(m.facing_error_rad));
    text += line;
  }
  for (const MemberDistance& d : distances) {
    std::snprintf(line, sizeof line, "  distance %u-%u: %.2f m\n", d.a, d.b, d.distance_m);
    text += line;
  }
  return text;
}

}  // namespace ari_social_sim::world
