#include "ari_social_sim/world/agent_grid.hpp"

#include "ari_social_sim/world/object.hpp"

namespace ari_social_sim::world {

void AgentGrid::rebuild(const std::vector<const Object*>& agents) {
  entries_.clear();
  for (const Object* agent : agents) {
    const Eigen::Vector2d centre = agent->centre();
    entries_.push_back({cell_key(cell_index(centre.x()), cell_index(centre.y())), agent, centre});
  }
  std::stable_sort(entries_.begin(), entries_.end(),
                   [](const Entry& a, const Entry& b) { return a.key < b.key; });
}

}  // namespace ari_social_sim::world
