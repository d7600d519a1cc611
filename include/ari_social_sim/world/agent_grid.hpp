#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace ari_social_sim::world {

class Object;

/// Agent centres bucketed in a uniform grid, for the neighbour queries every walker and group
/// member makes each step. A Box2D tree query costs more per agent as the crowd grows (a deeper
/// tree, and the room-sized boxes of the walls overlap every query); a grid lookup visits a fixed
/// number of cells, so the per-agent cost stays flat.
///
/// The grid is a snapshot: rebuild it whenever an agent moves, appears or disappears.
class AgentGrid {
 public:
  explicit AgentGrid(double cell_size_m) : cell_size_m_(cell_size_m) {}

  /// Replaces the snapshot. Agents keep their order within a cell, so queries are deterministic.
  void rebuild(const std::vector<const Object*>& agents);

  /// Calls `visit(object, centre)` for every agent whose cell overlaps the square of half side
  /// `radius_m` around `point`, cell by cell (rows, then columns) and in insertion order within a
  /// cell. Callers filter by exact distance.
  template <typename Visitor>
  void for_each_near(const Eigen::Vector2d& point, double radius_m, Visitor&& visit) const {
    const int64_t x_min = cell_index(point.x() - radius_m);
    const int64_t x_max = cell_index(point.x() + radius_m);
    const int64_t y_min = cell_index(point.y() - radius_m);
    const int64_t y_max = cell_index(point.y() + radius_m);
    for (int64_t y = y_min; y <= y_max; ++y) {
      // A row's cells are contiguous in key order: one search finds the first, then walk.
      auto entry = std::lower_bound(entries_.begin(), entries_.end(), cell_key(x_min, y),
                                    [](const Entry& e, uint64_t key) { return e.key < key; });
      const uint64_t last_key = cell_key(x_max, y);
      for (; entry != entries_.end() && entry->key <= last_key; ++entry) {
        visit(*entry->object, entry->centre);
      }
    }
  }

 private:
  struct Entry {
    uint64_t key;
    const Object* object;
    Eigen::Vector2d centre;
  };

  int64_t cell_index(double coordinate_m) const {
    return static_cast<int64_t>(std::floor(coordinate_m / cell_size_m_));
  }
  /// Row-major key, offset so that negative indices sort before positive ones.
  static uint64_t cell_key(int64_t x, int64_t y) {
    constexpr int64_t kOffset = int64_t{1} << 30;
    return (static_cast<uint64_t>(y + kOffset) << 32) | static_cast<uint64_t>(x + kOffset);
  }

  double cell_size_m_;
  std::vector<Entry> entries_;  // sorted by key, stable within a key
};

}  // namespace ari_social_sim::world
