#pragma once

#include <functional>
#include <map>
#include <string>
#include <utility>

namespace ari_social_sim::perception {

/// State kept per ROS4HRI id while the id is reported (hri_perception_node's per-id publishers):
/// made when an id first appears, dropped once the id has not been reported for a linger time,
/// so that an id missing for a frame or two keeps its state (its subscribers need not reconnect)
/// and memory follows the ids in use, not every id of the run. No ROS in it, so the soak
/// benchmark runs the node's bookkeeping as the node does.
template <class T>
class PerIdStore {
 public:
  using Make = std::function<T(const std::string& id)>;

  explicit PerIdStore(Make make) : make_(std::move(make)) {}

  /// The state of `id`, made on its first report; `now_s` (sim time) marks it reported.
  T& of(const std::string& id, double now_s) {
    auto [it, is_new] = entries_.try_emplace(id);
    if (is_new) {
      it->second.state = make_(id);
    }
    it->second.last_seen_s = now_s;
    return it->second.state;
  }

  /// Drops the ids last reported more than `linger_s` before `now_s`, and those reported after
  /// it (sim time went back: a world reset). With `linger_s` 0, every id not reported at `now_s`.
  void retire(double now_s, double linger_s) {
    for (auto it = entries_.begin(); it != entries_.end();) {
      const double age_s = now_s - it->second.last_seen_s;
      it = age_s > linger_s || age_s < 0.0 ? entries_.erase(it) : std::next(it);
    }
  }

  size_t size() const { return entries_.size(); }

 private:
  struct Entry {
    T state{};
    double last_seen_s{0.0};
  };

  Make make_;
  std::map<std::string, Entry> entries_;
};

}  // namespace ari_social_sim::perception
