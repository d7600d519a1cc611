#include "ari_social_sim/perception/transient_ids.hpp"

namespace ari_social_sim::perception {

std::string TransientIds::next() {
  // 26^5 = 11.9 million ids: a repeat is rare, and simply drawn again.
  std::string id(kLength, 'a');
  do {
    for (char& letter : id) {
      letter = static_cast<char>('a' + rng_.uniform_index(26));
    }
  } while (!issued_.insert(id).second);
  return id;
}

}  // namespace ari_social_sim::perception
