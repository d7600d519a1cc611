#include "ari_social_sim/perception/gcff.hpp"

#include <algorithm>
#include <cmath>

#include "ari_social_sim/core/check.hpp"
#include "ari_social_sim/core/config_check.hpp"

namespace ari_social_sim::perception {
namespace {

// GCFF's visibility term (Setti 2015): a person i stands "behind" j, seen from the o-space
// centre, when the directions to both differ by less than acos(0.75) ~ 41 degrees.
constexpr double kBehindCosine = 0.75;
// The penalty is 100^x; computed as exp(x ln 100) so that the cap can be tested on the exponent.
const double kLogPenaltyBase = std::log(100.0);
const double kLogMaxPenalty = std::log(kGcffMaxVisibilityPenalty);

// gcff_unary_costs with caller-owned scratch: `neighbours` receives M_k, `norms` |d_j| for M_k.
void fill_unary_costs(const std::vector<Eigen::Vector2d>& positions,
                      const std::vector<Eigen::Vector2d>& candidate_centres,
                      const std::vector<Eigen::Vector2d>& hypotheses, double mdl,
                      std::vector<double>& costs, std::vector<size_t>& neighbours,
                      std::vector<double>& norms) {
  const size_t person_count = positions.size();
  const size_t hypothesis_count = hypotheses.size();
  ARI_DCHECK(candidate_centres.size() == person_count);
  costs.resize(person_count * hypothesis_count);
  for (size_t k = 0; k < hypothesis_count; ++k) {
    const Eigen::Vector2d& centre = hypotheses[k];
    // Squared distance of every candidate centre to c_k; M_k = those closer than sqrt(mdl).
    neighbours.clear();
    norms.clear();
    for (size_t i = 0; i < person_count; ++i) {
      const double squared = (candidate_centres[i] - centre).squaredNorm();
      costs[i * hypothesis_count + k] = squared;
      if (squared < mdl) {
        neighbours.push_back(i);
        norms.push_back((positions[i] - centre).norm());
      }
    }
    // Visibility: i pays for every j of M_k that stands between i and c_k.
    for (size_t a = 0; a < neighbours.size(); ++a) {
      const double norm_i = norms[a];
      const Eigen::Vector2d d_i = positions[neighbours[a]] - centre;
      double penalty = 0.0;
      for (size_t b = 0; b < neighbours.size(); ++b) {
        const double norm_j = norms[b];
        if (b == a || norm_j <= 0.0 || norm_i <= norm_j) {
          continue;
        }
        const double cosine = d_i.dot(positions[neighbours[b]] - centre) / (norm_i * norm_j);
        if (cosine <= kBehindCosine) {
          continue;
        }
        const double exponent = cosine * norm_i / norm_j * kLogPenaltyBase;
        const double term =
            exponent >= kLogMaxPenalty ? kGcffMaxVisibilityPenalty : std::exp(exponent);
        penalty = std::min(penalty + term, kGcffMaxVisibilityPenalty);
      }
      costs[neighbours[a] * hypothesis_count + k] += penalty;
    }
  }
}

}  // namespace

void GcffParams::validate() const {
  core::check_fields(*this, "GcffParams");
}

Eigen::Vector2d gcff_candidate_centre(const GcffPerson& person, double stride) {
  return {person.x + stride * std::cos(person.theta), person.y + stride * std::sin(person.theta)};
}

void gcff_unary_costs(const std::vector<Eigen::Vector2d>& positions,
                      const std::vector<Eigen::Vector2d>& candidate_centres,
                      const std::vector<Eigen::Vector2d>& hypotheses, double mdl,
                      std::vector<double>& costs) {
  std::vector<size_t> neighbours;
  std::vector<double> norms;
  fill_unary_costs(positions, candidate_centres, hypotheses, mdl, costs, neighbours, norms);
}

GcffDetector::GcffDetector(const GcffParams& params) : params_(params) {
  params_.validate();
}

GcffResult GcffDetector::detect(const std::vector<GcffPerson>& persons) {
  GcffResult result;
  detect(persons, result);
  return result;
}

void GcffDetector::detect(const std::vector<GcffPerson>& persons, GcffResult& result) {
  // One hypothesis per person, placed on their candidate centre; person i starts with label i.
  person_count_ = persons.size();
  positions_.resize(person_count_);
  candidate_centres_.resize(person_count_);
  labels_.resize(person_count_);
  for (size_t i = 0; i < person_count_; ++i) {
    ARI_DCHECK(std::isfinite(persons[i].x) && std::isfinite(persons[i].y) &&
               std::isfinite(persons[i].theta));
    positions_[i] = {persons[i].x, persons[i].y};
    candidate_centres_[i] = gcff_candidate_centre(persons[i], params_.stride);
    labels_[i] = static_cast<int>(i);
  }
  hypotheses_ = candidate_centres_;
  hypothesis_count_ = person_count_;

  // Outer loop (1.2): solve, refit, until the labelling is stable. A lone person cannot change.
  result.iterations = 0;
  while (person_count_ > 1 && result.iterations < kMaxOuterIterations) {
    fill_unary_costs(positions_, candidate_centres_, hypotheses_, params_.mdl, unary_, neighbours_,
                     distances_);
    previous_labels_ = labels_;
    expand_until_stable();
    compact_and_refit();
    ++result.iterations;
    if (labels_ == previous_labels_) {
      break;
    }
  }

  // Groups: labels with two or more members; their hypothesis is already the mean centre.
  result.labels = labels_;
  label_sizes_.assign(hypothesis_count_, 0);
  for (const int label : labels_) {
    ++label_sizes_[label];
  }
  size_t group_count = 0;
  new_index_.assign(hypothesis_count_, -1);
  for (size_t k = 0; k < hypothesis_count_; ++k) {
    if (label_sizes_[k] >= 2) {
      new_index_[k] = static_cast<int>(group_count++);
    }
  }
  result.groups.resize(group_count);
  for (GcffGroup& group : result.groups) {
    group.members.clear();
  }
  for (size_t i = 0; i < person_count_; ++i) {
    const int group = new_index_[labels_[i]];
    if (group >= 0) {
      result.groups[group].members.push_back(i);
      result.groups[group].centre = hypotheses_[labels_[i]];
    }
  }
}

double GcffDetector::energy() {
  label_sizes_.assign(hypothesis_count_, 0);
  double total = 0.0;
  for (size_t i = 0; i < person_count_; ++i) {
    total += unary_[i * hypothesis_count_ + labels_[i]];
    ++label_sizes_[labels_[i]];
  }
  for (const int size : label_sizes_) {
    if (size > 0) {
      total += params_.mdl;
    }
  }
  return total;
}

void GcffDetector::expand_until_stable() {
  const size_t count = hypothesis_count_;
  double current_energy = energy();
  size_t expansions_without_gain = 0;
  size_t alpha = 0;
  while (expansions_without_gain < count) {
    saved_labels_ = labels_;

    // Per label j != alpha: the sum of Delta_i = u(i,alpha) - u(i,j) over its members, and of the
    // negative Delta_i only.
    delta_sum_.assign(count, 0.0);
    negative_delta_sum_.assign(count, 0.0);
    const double* unary = unary_.data();
    for (size_t i = 0; i < person_count_; ++i) {
      const size_t label = labels_[i];
      if (label != alpha) {
        const double delta = unary[i * count + alpha] - unary[i * count + label];
        delta_sum_[label] += delta;
        negative_delta_sum_[label] += std::min(delta, 0.0);
      }
    }

    // The closed-form move (1.2): per label, option A (all members go to alpha, the label's cost
    // is saved) when strictly cheaper than option B (only the members that gain go).
    for (size_t i = 0; i < person_count_; ++i) {
      const size_t label = labels_[i];
      if (label == alpha) {
        continue;
      }
      const bool move_all = delta_sum_[label] - params_.mdl < negative_delta_sum_[label];
      if (move_all || unary[i * count + alpha] < unary[i * count + label]) {
        labels_[i] = static_cast<int>(alpha);
      }
    }

    // Accept a strict decrease, keep an equal energy, revert an increase (alpha's own label
    // cost only shows up here).
    const double new_energy = energy();
    if (new_energy < current_energy) {
      current_energy = new_energy;
      expansions_without_gain = 0;
    } else {
      if (new_energy > current_energy) {
        labels_.swap(saved_labels_);
      }
      ++expansions_without_gain;
    }
    alpha = (alpha + 1) % count;
  }
}

void GcffDetector::compact_and_refit() {
  // Sizes and candidate-centre sums per old label.
  label_sizes_.assign(hypothesis_count_, 0);
  centre_sums_.assign(hypothesis_count_, Eigen::Vector2d::Zero());
  for (size_t i = 0; i < person_count_; ++i) {
    ++label_sizes_[labels_[i]];
    centre_sums_[labels_[i]] += candidate_centres_[i];
  }
  // Used labels keep their order; new index <= old index, so hypotheses_ is rewritten in place.
  new_index_.assign(hypothesis_count_, -1);
  size_t used = 0;
  for (size_t k = 0; k < hypothesis_count_; ++k) {
    if (label_sizes_[k] > 0) {
      hypotheses_[used] = centre_sums_[k] / label_sizes_[k];
      new_index_[k] = static_cast<int>(used++);
    }
  }
  hypotheses_.resize(used);
  hypothesis_count_ = used;
  for (int& label : labels_) {
    label = new_index_[label];
  }
}

}  // namespace ari_social_sim::perception
