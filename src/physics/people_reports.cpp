#include "ari_social_sim/physics/people_reports.hpp"

namespace ari_social_sim::physics {

namespace {
// Stamps closer than this are the same instant (sim time from nanosecond stamps).
constexpr double kSameTime_s = 1e-6;
}  // namespace

void PeopleReports::add(double time_s, std::vector<PersonState> people) {
  if (newest_s_ && time_s < *newest_s_ - kSameTime_s) {
    reports_.clear();
    handed_out_s_.reset();
  }
  reports_.emplace_back(time_s, std::move(people));
  newest_s_ = time_s;
  while (reports_.size() > kCapacity) {
    reports_.pop_front();
  }
}

bool PeopleReports::has_report_for(double time_s) const {
  return !newest_s_ || *newest_s_ >= time_s - kSameTime_s;
}

std::optional<std::vector<PersonState>> PeopleReports::take_for(double step_end_s) {
  // Keep the newest even when it is older than the step: it is the best there is.
  while (reports_.size() > 1 && reports_.front().first < step_end_s - kSameTime_s) {
    reports_.pop_front();
  }
  if (reports_.empty()) {
    return std::nullopt;
  }
  const double stamp_s = reports_.front().first;
  if (handed_out_s_ && std::abs(*handed_out_s_ - stamp_s) <= kSameTime_s) {
    return std::nullopt;
  }
  handed_out_s_ = stamp_s;
  return reports_.front().second;
}

}  // namespace ari_social_sim::physics
