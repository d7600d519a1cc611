#include "ari_social_sim/navigation/geodesic_field.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <queue>

namespace ari_social_sim::navigation {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

struct Frontier {
  float value;
  int cell;
  bool operator>(const Frontier& other) const { return value > other.value; }
};

// First-order upwind solution of |grad T| = f at one cell from its neighbours' times a (along x)
// and b (along y), grid spacing h.
float eikonal_update(float a, float b, float f, float h) {
  if (a > b) {
    std::swap(a, b);
  }
  const float step = f * h;
  if (b - a >= step || b == kInfinity) {
    return a + step;
  }
  return 0.5f * (a + b + std::sqrt(2.0f * step * step - (a - b) * (a - b)));
}

}  // namespace

GeodesicField::GeodesicField(const GridField& sdf, const Eigen::Vector2d& goal,
                             const GeodesicParams& params, const std::vector<CostDisc>& discs)
    : field_(sdf), goal_(goal), params_(params) {
  const size_t count = sdf.values().size();
  std::vector<float> cost_per_m(count);
  passable_.assign(count, 0);
  const double spare_range =
      std::max(params.preferred_clearance_m - params.inscribed_radius_m, 1e-6);
  for (size_t i = 0; i < count; ++i) {
    const double clearance = sdf.values()[i];
    if (clearance < params.inscribed_radius_m) {
      cost_per_m[i] = static_cast<float>(params.blocked_cost);
      continue;
    }
    passable_[i] = 1;
    const double shortfall =
        std::max(0.0, (params.preferred_clearance_m - clearance) / spare_range);
    cost_per_m[i] = static_cast<float>(1.0 + params.clearance_penalty * shortfall * shortfall);
  }
  // Cost discs: the largest extra cost of the discs covering a cell.
  for (const CostDisc& disc : discs) {
    int x0, y0, x1, y1;
    const Eigen::Vector2d reach(disc.radius_m, disc.radius_m);
    field_.cell_of(disc.centre - reach, x0, y0);
    field_.cell_of(disc.centre + reach, x1, y1);
    for (int y = std::max(y0, 0); y <= std::min(y1, field_.height() - 1); ++y) {
      for (int x = std::max(x0, 0); x <= std::min(x1, field_.width() - 1); ++x) {
        if ((field_.cell_centre(x, y) - disc.centre).norm() <= disc.radius_m) {
          const size_t i = field_.index(x, y);
          if (passable_[i]) {
            const float base = cost_per_m[i];
            cost_per_m[i] = std::max(base, static_cast<float>(1.0 + disc.extra_cost));
          }
        }
      }
    }
  }
  march(cost_per_m);
  flood_passable();
}

void GeodesicField::march(const std::vector<float>& cost_per_m) {
  const int w = field_.width(), h = field_.height();
  std::fill(field_.values().begin(), field_.values().end(), kInfinity);
  if (w == 0 || h == 0) {
    return;
  }
  std::vector<uint8_t> accepted(field_.values().size(), 0);
  std::priority_queue<Frontier, std::vector<Frontier>, std::greater<Frontier>> heap;
  // Seed the four cell centres around the goal with their straight-line cost, so the interpolated
  // field reaches ~0 at the goal itself rather than at a cell centre.
  const double res = field_.resolution_m();
  const Eigen::Vector2d local = (goal_ - field_.origin()) / res - Eigen::Vector2d(0.5, 0.5);
  const int gx = static_cast<int>(std::floor(local.x()));
  const int gy = static_cast<int>(std::floor(local.y()));
  for (int dy = 0; dy <= 1; ++dy) {
    for (int dx = 0; dx <= 1; ++dx) {
      const int x = std::clamp(gx + dx, 0, w - 1), y = std::clamp(gy + dy, 0, h - 1);
      const size_t i = field_.index(x, y);
      const float value =
          static_cast<float>((field_.cell_centre(x, y) - goal_).norm()) * cost_per_m[i];
      if (value < field_.values()[i]) {
        field_.values()[i] = value;
        heap.push({value, static_cast<int>(i)});
      }
    }
  }
  const float hf = static_cast<float>(res);
  const int offsets[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
  std::vector<float>& t = field_.values();
  while (!heap.empty()) {
    const Frontier top = heap.top();
    heap.pop();
    if (accepted[top.cell] || top.value > t[top.cell]) {
      continue;
    }
    accepted[top.cell] = 1;
    const int cx = top.cell % w, cy = top.cell / w;
    for (const auto& offset : offsets) {
      const int nx = cx + offset[0], ny = cy + offset[1];
      if (nx < 0 || ny < 0 || nx >= w || ny >= h) {
        continue;
      }
      const size_t n = field_.index(nx, ny);
      if (accepted[n]) {
        continue;
      }
      const float a = std::min(nx > 0 ? t[n - 1] : kInfinity, nx < w - 1 ? t[n + 1] : kInfinity);
      const float b = std::min(ny > 0 ? t[n - w] : kInfinity, ny < h - 1 ? t[n + w] : kInfinity);
      const float value = eikonal_update(a, b, cost_per_m[n], hf);
      if (value < t[n]) {
        t[n] = value;
        heap.push({value, static_cast<int>(n)});
      }
    }
  }
}

template <class Visit>
void GeodesicField::for_each_near(const Eigen::Vector2d& point, Visit visit) const {
  const double res = field_.resolution_m();
  const int reach = static_cast<int>(std::ceil(params_.snap_radius_m / res));
  int px, py;
  field_.cell_of(point, px, py);
  for (int y = std::max(py - reach, 0); y <= std::min(py + reach, field_.height() - 1); ++y) {
    for (int x = std::max(px - reach, 0); x <= std::min(px + reach, field_.width() - 1); ++x) {
      const size_t i = field_.index(x, y);
      if (passable_[i] && (field_.cell_centre(x, y) - point).norm() <= params_.snap_radius_m) {
        visit(i);
      }
    }
  }
}

void GeodesicField::flood_passable() {
  joined_.assign(passable_.size(), 0);
  std::deque<size_t> queue;
  for_each_near(goal_, [&](size_t i) {
    if (!joined_[i]) {
      joined_[i] = 1;
      queue.push_back(i);
    }
  });
  const int w = field_.width(), h = field_.height();
  while (!queue.empty()) {
    const size_t i = queue.front();
    queue.pop_front();
    const int cx = static_cast<int>(i % w), cy = static_cast<int>(i / w);
    const int offsets[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    for (const auto& offset : offsets) {
      const int nx = cx + offset[0], ny = cy + offset[1];
      if (nx < 0 || ny < 0 || nx >= w || ny >= h) {
        continue;
      }
      const size_t n = field_.index(nx, ny);
      if (passable_[n] && !joined_[n]) {
        joined_[n] = 1;
        queue.push_back(n);
      }
    }
  }
}

bool GeodesicField::reachable(const Eigen::Vector2d& point) const {
  bool found = false;
  for_each_near(point, [&](size_t i) { found = found || joined_[i] != 0; });
  return found;
}

}  // namespace ari_social_sim::navigation
