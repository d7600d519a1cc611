#include "ari_social_sim/world/walking_route.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

#include "ari_social_sim/world/map_sensor.hpp"

namespace ari_social_sim::world {
namespace {

// Below this clearance (m) a cell costs more, up to 1 + kClearancePenalty times a free cell at
// the least passable clearance: routes keep to the middle of doors and corridors, where an
// abreast group has the most room.
constexpr double kPreferredClearanceM = 1.0;
constexpr double kClearancePenalty = 3.0;
// A start or goal this close (m) to a passable cell counts as on it: a group's centroid may stand
// nearer to furniture than the route's clearance.
constexpr double kSnapRadiusM = 0.5;
// Cells averaged on either side of a route point: the grid's 45-degree steps become a line.
constexpr int kSmoothingCells = 3;
// Half the chord (m) the walking direction is measured over: a row of four, 2.25 m long, turns
// with the grid's single-cell steps by a few degrees only.
constexpr double kHeadingChordM = 1.0;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The occupancy grid with each cell's clearance (m) from the nearest occupied cell or the floor's
// edge.
struct ClearanceGrid {
  model::OccupancyGrid map;
  std::vector<double> clearance_m;

  size_t index(int x, int y) const { return static_cast<size_t>(y) * map.width + x; }
  bool passable(int x, int y, double clearance) const {
    return x >= 0 && y >= 0 && x < map.width && y < map.height &&
           clearance_m[index(x, y)] >= clearance;
  }
};

ClearanceGrid clearance_grid(const model::WorldDescription& world) {
  ClearanceGrid grid;
  grid.map = rasterize_static_map(world, kRouteCellM);
  const int w = grid.map.width;
  const int h = grid.map.height;
  // Distances between cell centres, in cells, to the nearest occupied cell or to a cell just off
  // the grid (the floor's edge): a two-pass chamfer transform with steps 1 and sqrt 2, within
  // 8 % of the Euclidean distance.
  std::vector<double> d(static_cast<size_t>(w) * h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      d[grid.index(x, y)] = grid.map.at(x, y) == model::OccupancyGrid::kFree
                                ? std::min({x + 1, y + 1, w - x, h - y})
                                : 0.0;
    }
  }
  const double diagonal = std::sqrt(2.0);
  auto relax = [&](int x, int y, int dx, int dy, double step) {
    const int nx = x + dx;
    const int ny = y + dy;
    if (nx >= 0 && ny >= 0 && nx < w && ny < h) {
      d[grid.index(x, y)] = std::min(d[grid.index(x, y)], d[grid.index(nx, ny)] + step);
    }
  };
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      relax(x, y, -1, 0, 1.0);
      relax(x, y, 0, -1, 1.0);
      relax(x, y, -1, -1, diagonal);
      relax(x, y, 1, -1, diagonal);
    }
  }
  for (int y = h - 1; y >= 0; --y) {
    for (int x = w - 1; x >= 0; --x) {
      relax(x, y, 1, 0, 1.0);
      relax(x, y, 0, 1, 1.0);
      relax(x, y, 1, 1, diagonal);
      relax(x, y, -1, 1, diagonal);
    }
  }
  // An occupied cell's edge lies half a cell from its centre.
  grid.clearance_m.resize(d.size());
  for (size_t i = 0; i < d.size(); ++i) {
    grid.clearance_m[i] = (d[i] - 0.5) * grid.map.resolution_m;
  }
  return grid;
}

// The passable cell nearest to `point` within kSnapRadiusM, or false.
bool snap(const ClearanceGrid& grid, const Eigen::Vector2d& point, double clearance, int& cx,
          int& cy) {
  const int reach = static_cast<int>(std::ceil(kSnapRadiusM / grid.map.resolution_m));
  int x0 = 0;
  int y0 = 0;
  if (!grid.map.cell_of(point, x0, y0)) {
    return false;
  }
  double best = kInfinity;
  for (int y = y0 - reach; y <= y0 + reach; ++y) {
    for (int x = x0 - reach; x <= x0 + reach; ++x) {
      if (!grid.passable(x, y, clearance)) {
        continue;
      }
      const double distance = (grid.map.cell_centre(x, y) - point).norm();
      if (distance <= kSnapRadiusM && distance < best) {
        best = distance;
        cx = x;
        cy = y;
      }
    }
  }
  return std::isfinite(best);
}

// The cells from start to goal of the cheapest route (Dijkstra from the start cell; a step costs
// its length, more where clearance is short); empty when the goal cannot be reached.
std::vector<size_t> cheapest_cells(const ClearanceGrid& grid, size_t start_index, size_t goal_index,
                                   double clearance_m) {
  const size_t cells = grid.clearance_m.size();
  std::vector<double> cost(cells, kInfinity);
  std::vector<int64_t> parent(cells, -1);
  using Entry = std::pair<double, size_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
  cost[start_index] = 0.0;
  open.push({0.0, start_index});
  const int w = grid.map.width;
  while (!open.empty()) {
    const auto [c, i] = open.top();
    open.pop();
    if (c > cost[i]) {
      continue;
    }
    if (i == goal_index) {
      break;
    }
    const int x = static_cast<int>(i % w);
    const int y = static_cast<int>(i / w);
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        if ((dx == 0 && dy == 0) || !grid.passable(x + dx, y + dy, clearance_m)) {
          continue;
        }
        const size_t j = grid.index(x + dx, y + dy);
        const double shortfall =
            std::max(0.0, kPreferredClearanceM - grid.clearance_m[j]) / kPreferredClearanceM;
        const double next =
            c + std::hypot(dx, dy) * grid.map.resolution_m * (1.0 + kClearancePenalty * shortfall);
        if (next < cost[j]) {
          cost[j] = next;
          parent[j] = static_cast<int64_t>(i);
          open.push({next, j});
        }
      }
    }
  }
  std::vector<size_t> chain;
  if (!std::isfinite(cost[goal_index])) {
    return chain;
  }
  for (int64_t i = static_cast<int64_t>(goal_index); i >= 0; i = parent[static_cast<size_t>(i)]) {
    chain.push_back(static_cast<size_t>(i));
  }
  std::reverse(chain.begin(), chain.end());
  return chain;
}

}  // namespace

std::optional<WalkingRoute> WalkingRoute::plan(const model::WorldDescription& world,
                                               const Eigen::Vector2d& start,
                                               const Eigen::Vector2d& goal, double clearance_m) {
  const ClearanceGrid grid = clearance_grid(world);
  int sx = 0;
  int sy = 0;
  int gx = 0;
  int gy = 0;
  if (!snap(grid, start, clearance_m, sx, sy) || !snap(grid, goal, clearance_m, gx, gy)) {
    return std::nullopt;
  }

  const size_t start_index = grid.index(sx, sy);
  const size_t goal_index = grid.index(gx, gy);
  const std::vector<size_t> chain = cheapest_cells(grid, start_index, goal_index, clearance_m);
  if (chain.empty()) {
    return std::nullopt;
  }

  // The cells from start to goal, averaged over their neighbours along the route, between the
  // true start and goal.
  const int w = grid.map.width;
  std::vector<Eigen::Vector2d> centres;
  centres.reserve(chain.size());
  for (size_t i : chain) {
    centres.push_back(grid.map.cell_centre(static_cast<int>(i % w), static_cast<int>(i / w)));
  }
  WalkingRoute route;
  route.points_.push_back(start);
  route.clearance_m_.push_back(grid.clearance_m[start_index]);
  const int n = static_cast<int>(centres.size());
  for (int k = 1; k + 1 < n; ++k) {
    const int half = std::min({kSmoothingCells, k, n - 1 - k});
    Eigen::Vector2d sum = Eigen::Vector2d::Zero();
    for (int m = k - half; m <= k + half; ++m) {
      sum += centres[static_cast<size_t>(m)];
    }
    route.points_.emplace_back(sum / (2 * half + 1));
    route.clearance_m_.push_back(grid.clearance_m[chain[static_cast<size_t>(k)]]);
  }
  route.points_.push_back(goal);
  route.clearance_m_.push_back(grid.clearance_m[goal_index]);
  route.arc_m_.push_back(0.0);
  for (size_t k = 1; k < route.points_.size(); ++k) {
    route.arc_m_.push_back(route.arc_m_.back() + (route.points_[k] - route.points_[k - 1]).norm());
  }
  return route;
}

Eigen::Vector2d WalkingRoute::point_at(double s_m) const {
  if (s_m <= 0.0) {
    return points_.front();
  }
  if (s_m >= length_m()) {
    return points_.back();
  }
  const size_t k =
      static_cast<size_t>(std::upper_bound(arc_m_.begin(), arc_m_.end(), s_m) - arc_m_.begin());
  const double segment = arc_m_[k] - arc_m_[k - 1];
  const double t = segment > 0.0 ? (s_m - arc_m_[k - 1]) / segment : 0.0;
  return points_[k - 1] + t * (points_[k] - points_[k - 1]);
}

double WalkingRoute::heading_at(double s_m) const {
  const Eigen::Vector2d chord = point_at(s_m + kHeadingChordM) - point_at(s_m - kHeadingChordM);
  if (chord.squaredNorm() > 1e-12) {
    return std::atan2(chord.y(), chord.x());
  }
  const Eigen::Vector2d whole = points_.back() - points_.front();
  return whole.squaredNorm() > 1e-12 ? std::atan2(whole.y(), whole.x()) : 0.0;
}

double WalkingRoute::min_clearance_m(double s0_m, double s1_m) const {
  double least = kInfinity;
  for (size_t k = 0; k < points_.size(); ++k) {
    if (arc_m_[k] >= s0_m && arc_m_[k] <= s1_m) {
      least = std::min(least, clearance_m_[k]);
    }
  }
  return least;
}

}  // namespace ari_social_sim::world
