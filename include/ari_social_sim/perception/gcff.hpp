#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <string>
#include <vector>

#include "ari_social_sim/core/config_fields.hpp"

// GCFF: Graph-Cuts for F-Formation (Setti, Russell, Bassetti, Cristani, PLOS ONE 2015), as
// the paper and its authors' code define it. Every length here is in the unit of the input
// positions: metres in the simulator, centimetres for the F-formation data sets (MDL then scales by
// 10^4).

namespace ari_social_sim::perception {

/// Parameters of GCFF. Lengths are in the positions' unit (m in the simulator).
struct GcffParams {
  double stride{0.5};
  double mdl{0.8};

  // The F-formation data sets, in cm, use strides of 20-50 and an mdl of 6000-8000.
  template <class V>
  void visit(V& v) {
    v.field("stride", stride,
            "distance from a person to their candidate o-space centre, straight ahead (typical "
            "0.5-0.7 m)",
            core::positive());
    // Also bounds the neighbourhood of the visibility term.
    v.field("mdl", mdl,
            "label cost (unit^2), the price of one more group: sqrt(mdl) is about the distance at "
            "which a new group beats joining one (typical 0.8-3 m^2)",
            core::positive());
  }

  /// Throws core::ConfigError naming the field unless both are finite and > 0.
  void validate() const;
};

/// One person as GCFF sees them.
struct GcffPerson {
  std::string id;     ///< Copied through; GCFF does not use it.
  double x{0.0};      ///< Position (unit of GcffParams::stride).
  double y{0.0};      ///< Position (unit of GcffParams::stride).
  double theta{0.0};  ///< Facing direction of the body, rad, counter-clockwise from +x.
};

/// A detected F-formation: two or more people sharing an o-space.
struct GcffGroup {
  std::vector<size_t> members;       ///< Indices into the input persons, ascending.
  Eigen::Vector2d centre{0.0, 0.0};  ///< O-space centre: mean of the members' candidate centres.
};

/// What GcffDetector::detect finds in one frame.
struct GcffResult {
  /// Label per input person, 0..K-1 in order of the labels' first hypothesis; people sharing a
  /// label form a group when there are two or more of them, otherwise they stand alone.
  std::vector<int> labels;
  /// Labels with >= 2 members, in label order.
  std::vector<GcffGroup> groups;
  /// Outer (solve, refit) iterations run, at most GcffDetector::kMaxOuterIterations.
  int iterations{0};
};

/// Ceiling of the visibility penalty V(i,k): 100^x overflows to inf for x > 154.
constexpr double kGcffMaxVisibilityPenalty = 1e12;

/// Candidate o-space centre of one person (Setti 2015): p + stride (cos theta, sin theta).
Eigen::Vector2d gcff_candidate_centre(const GcffPerson& person, double stride);

/// Unary costs u(i,k) = |mu_i - c_k|^2 + V(i,k) (Setti 2015) of every person against
/// every hypothesis centre, written row-major into `costs` (N rows, K columns; resized).
/// `positions` and `candidate_centres` hold p_i and mu_i for the N persons, `hypotheses` the c_k.
/// V(i,k) sums 100^(cos(d_i, d_j) |d_i| / |d_j|) over the people j that person i stands behind
/// (|d_i| > |d_j|, cos > 0.75), d = position - c_k, among those whose candidate centre lies within
/// sqrt(mdl) of c_k; a j standing exactly on c_k has no direction and is skipped. V is capped at
/// kGcffMaxVisibilityPenalty.
void gcff_unary_costs(const std::vector<Eigen::Vector2d>& positions,
                      const std::vector<Eigen::Vector2d>& candidate_centres,
                      const std::vector<Eigen::Vector2d>& hypotheses, double mdl,
                      std::vector<double>& costs);

/// Finds F-formations in one frame (Setti 2015): starting from one hypothesis per person,
/// alternates alpha-expansion with label costs (closed-form moves, no graph-cut library) and a
/// refit of each hypothesis to the mean of its members' candidate centres, until the labelling
/// stops changing or after kMaxOuterIterations. Deterministic.
///
/// Keeps scratch buffers between calls: reuse one detector (and one result) per stream of frames
/// to avoid allocations. Not thread-safe; use one detector per thread.
class GcffDetector {
 public:
  static constexpr int kMaxOuterIterations = 10;

  /// Throws core::ConfigError if `params` is invalid.
  explicit GcffDetector(const GcffParams& params);

  /// Detects the groups among `persons` into `result` (its buffers are reused). Any number of
  /// persons, including 0 and 1. Coordinates must be finite.
  void detect(const std::vector<GcffPerson>& persons, GcffResult& result);
  GcffResult detect(const std::vector<GcffPerson>& persons);

  const GcffParams& params() const { return params_; }

 private:
  /// Minimises the energy over the current hypotheses, starting from `labels_`.
  void expand_until_stable();
  /// Energy of `labels_`: sum of unaries plus mdl per label in use.
  double energy();
  /// Relabels `labels_` to 0..K'-1 (keeping label order) and moves each hypothesis to the mean
  /// candidate centre of its members.
  void compact_and_refit();

  GcffParams params_;
  size_t person_count_{0};
  size_t hypothesis_count_{0};
  std::vector<Eigen::Vector2d> positions_;
  std::vector<Eigen::Vector2d> candidate_centres_;
  std::vector<Eigen::Vector2d> hypotheses_;
  std::vector<double> unary_;  ///< Row-major person x hypothesis.
  std::vector<int> labels_;
  std::vector<int> saved_labels_;     ///< Before the current expansion, for a revert.
  std::vector<int> previous_labels_;  ///< Before the current outer iteration.
  std::vector<int> label_sizes_;
  std::vector<int> new_index_;
  std::vector<double> delta_sum_;
  std::vector<double> negative_delta_sum_;
  std::vector<Eigen::Vector2d> centre_sums_;
  std::vector<size_t> neighbours_;
  std::vector<double> distances_;
};

}  // namespace ari_social_sim::perception
