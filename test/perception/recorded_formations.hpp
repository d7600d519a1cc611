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
  std::map<std::string, int> groups_of_set;  // by data set: their annotations differ
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
        FormationSpread& spread = spreads[{ids.size(), model::to_string(geometry.arrangement)}];
        spread.add(geometry);
        ++spread.groups_of_set[set];
      }
    }
  }
  return spreads;
}

/// The step (rad) in which a data set's annotators marked facings: CoffeeBreak's in quarter turns,
/// Synth's in multiples of 15 degrees (its facings are 0, 30, 45, 90, 120, 135, ... degrees).
inline double annotated_facing_step_rad(const std::string& set) {
  return set.rfind("CoffeeBreak", 0) == 0 ? M_PI / 2.0 : M_PI / 12.0;
}

/// A facing as an annotator marking in steps of `step_rad` would have: the nearest multiple.
inline double annotated_facing(double theta_rad, double step_rad) {
  return step_rad * std::round(theta_rad / step_rad);
}

/// A 10th-90th percentile band.
struct Band {
  double low{0.0}, high{0.0};
};

inline Band band_of(const std::vector<double>& values) {
  return {percentile(values, 0.1), percentile(values, 0.9)};
}

/// How much of the recorded band the world's covers: |intersection| / |recorded band| (1 when
/// the recorded band is a single value the world's band holds).
inline double band_overlap(const Band& world, const Band& recorded) {
  const double common = std::min(world.high, recorded.high) - std::max(world.low, recorded.low);
  const double width = recorded.high - recorded.low;
  if (width <= 0.0) {
    return world.low <= recorded.low && recorded.low <= world.high ? 1.0 : 0.0;
  }
  return std::max(0.0, common) / width;
}

/// Change of facing (deg, 0-180) as the CoffeeBreak annotators would have marked it: both facings
/// rounded to a multiple of 90 degrees first.
inline double quadrant_turn_deg(double from_rad, double to_rad) {
  auto quadrant = [](double theta) { return std::lround(theta / (M_PI / 2.0)); };
  const long steps = ((quadrant(to_rad) - quadrant(from_rad)) % 4 + 4) % 4;
  return 90.0 * static_cast<double>(steps == 3 ? 1 : steps);
}

/// How members of standing groups move between two looks: each member's displacement (m), the
/// change of its facing (deg), and that change with both facings rounded to multiples of 90 deg.
struct MemberMotion {
  int members{0};
  std::vector<double> displacement_m, turn_deg, quadrant_turn_deg;
};

/// The members of the recorded CoffeeBreak groups (sequences 1 and 2) of each size whose group
/// is the same in two consecutive annotated frames, between those frames. Synth is left out: its
/// people are drawn, not recorded, and barely move between frames (a median of 5 mm).
inline std::map<size_t, MemberMotion> recorded_member_motion() {
  std::map<size_t, MemberMotion> motion;
  for (const char* set : {"CoffeeBreak_Seq1", "CoffeeBreak_Seq2"}) {
    const std::string stem = core::data_set_dir("fformation") + "/" + set;
    const FeatureTable features = read_fformation_features(stem + "_features.csv");
    const GroupTable groups = read_fformation_groups(stem + "_groups.csv");
    auto person = [&features](FrameId frame, const std::string& id) -> const GcffPerson* {
      const auto people = features.find(frame);
      if (people == features.end()) {
        return nullptr;
      }
      const auto found = std::find_if(people->second.begin(), people->second.end(),
                                      [&id](const GcffPerson& p) { return p.id == id; });
      return found == people->second.end() ? nullptr : &*found;
    };
    for (const auto& [frame, grouping] : groups) {
      const auto next = groups.find(frame + 1);
      if (next == groups.end()) {
        continue;
      }
      for (std::vector<std::string> ids : grouping) {
        std::sort(ids.begin(), ids.end());
        const bool kept = std::any_of(next->second.begin(), next->second.end(),
                                      [&ids](std::vector<std::string> later) {
                                        std::sort(later.begin(), later.end());
                                        return later == ids;
                                      });
        for (const std::string& id : ids) {
          const GcffPerson* before = person(frame, id);
          const GcffPerson* after = person(frame + 1, id);
          if (!kept || before == nullptr || after == nullptr) {
            continue;
          }
          MemberMotion& m = motion[ids.size()];
          ++m.members;
          m.displacement_m.push_back(std::hypot(after->x - before->x, after->y - before->y) /
                                     100.0);
          const double turn = std::abs(std::remainder(after->theta - before->theta, 2.0 * M_PI));
          m.turn_deg.push_back(turn * 180.0 / M_PI);
          m.quadrant_turn_deg.push_back(quadrant_turn_deg(before->theta, after->theta));
        }
      }
    }
  }
  return motion;
}

}  // namespace ari_social_sim::perception::test
