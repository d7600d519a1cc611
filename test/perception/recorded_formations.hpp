#pragma once

// The geometry of the recorded conversational groups (Synth, CoffeeBreak 1 and 2; positions in
// metres) by size and arrangement: the spread the world's groups are compared with
// (docs/perception_gcff.md, docs/world.md).

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "ari_social_sim/core/data_sets.hpp"
#include "ari_social_sim/perception/fformation_dataset.hpp"
#include "ari_social_sim/perception/fformation_geometry.hpp"

namespace ari_social_sim::perception::test {

/// The stride both the recorded and the world's groups are measured with: perception's
/// (config/perception.yaml groups.stride). A group's distance to its o-space centre grows with the
/// stride (a row facing one way stands a stride from it), so groups measured with different
/// strides would compare the strides rather than the people; the sets' own published strides
/// (0.2-0.5 m) were tuned for detection, not for measuring.
constexpr double kComparisonStrideM = 0.6;

/// Every member's distance to the centre, every pair's distance and every facing offset (deg) of
/// the groups of one size and arrangement.
struct FormationSpread {
  int groups{0};
  std::vector<double> centre_m, pair_m, offset_deg;

  void add(const FormationGeometry& geometry) {
    ++groups;
    centre_m.insert(centre_m.end(), geometry.centre_distances.begin(),
                    geometry.centre_distances.end());
    pair_m.insert(pair_m.end(), geometry.pair_distances.begin(), geometry.pair_distances.end());
    for (const double offset : geometry.facing_offsets_rad) {
      offset_deg.push_back(offset * 180.0 / M_PI);
    }
  }
};

using SpreadKey = std::pair<size_t, std::string>;  // size, arrangement name

/// Percentile p (0-1) of values, by nearest rank.
inline double percentile(std::vector<double> values, double p) {
  std::sort(values.begin(), values.end());
  const size_t rank = static_cast<size_t>(std::lround(p * (values.size() - 1)));
  return values[rank];
}

/// The recorded groups of 2 to 4, classified by classify_arrangement, from the F-formation data
/// set (callers skip without it: ARI_SKIP_WITHOUT_DATA_SET). Throws if a set cannot be read; a
/// member missing from its frame's features is skipped with its group.
inline std::map<SpreadKey, FormationSpread> recorded_formation_spreads() {
  std::map<SpreadKey, FormationSpread> spreads;
  for (const char* set : {"Synth", "CoffeeBreak_Seq1", "CoffeeBreak_Seq2"}) {
    const std::string stem = core::data_set_dir("fformation") + "/" + set;
    const FeatureTable features = read_fformation_features(stem + "_features.csv");
    const GroupTable groups = read_fformation_groups(stem + "_groups.csv");
    for (const auto& [frame, grouping] : groups) {
      const std::vector<GcffPerson>& people = features.at(frame);
      for (const std::vector<std::string>& ids : grouping) {
        if (ids.size() < 2 || ids.size() > 4) {
          continue;
        }
        std::vector<GcffPerson> members;
        for (const std::string& id : ids) {
          const auto found = std::find_if(people.begin(), people.end(),
                                          [&id](const GcffPerson& p) { return p.id == id; });
          if (found != people.end()) {
            members.push_back({id, found->x / 100.0, found->y / 100.0, found->theta});
          }
        }
        if (members.size() != ids.size()) {
          continue;
        }
        const FormationGeometry geometry = formation_geometry(members, kComparisonStrideM);
        spreads[{ids.size(), model::to_string(geometry.arrangement)}].add(geometry);
      }
    }
  }
  return spreads;
}

}  // namespace ari_social_sim::perception::test
