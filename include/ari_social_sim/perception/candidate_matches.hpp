#pragma once

#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "ari_social_sim/core/rng.hpp"
#include "ari_social_sim/perception/perception_config.hpp"
#include "ari_social_sim/perception/perception_frame.hpp"

namespace ari_social_sim::perception {

/// The kinds of ROS4HRI ids; values are hri_msgs/IdsMatch's.
enum class IdKind : uint8_t { kPerson = 1, kFace = 2, kBody = 3, kVoice = 4 };

/// One hri_msgs/IdsMatch: "id1 and id2 belong to the same person, with this confidence".
struct CandidateMatch {
  std::string id1;
  IdKind kind1{IdKind::kPerson};
  std::string id2;
  IdKind kind2{IdKind::kPerson};
  double confidence{1.0};
};

/// What the person manager settled for a frame: each face, body and voice matched to its person
/// with confidence 1 (what hri_perception_node sends in sim mode, where it is the person manager).
std::vector<CandidateMatch> person_links(const PerceptionFrame& frame);

/// What ROS4HRI's matchers would send on /humans/candidate_matches about a frame's detections,
/// for a person manager (hri_person_manager) to make persons from (detectors mode):
/// - a face-body matcher (hri_face_body_matcher): body -> face of the same human when both are
///   detected, with a noisy confidence;
/// - a face identifier (hri_face_identification): person -> face for the face tracks it
///   recognises (decided once per track, MatcherConfig::recognition_rate); an unrecognised face
///   leaves the person manager to make an anonymous person;
/// - a speaker localiser: body -> voice of the same human when both are detected.
/// Confidences at or below MatcherConfig::threshold are not sent, as the matchers do. Seeded.
class CandidateMatcher {
 public:
  /// s of sim time a face id's recognition verdict is kept after the face was last in a frame:
  /// a face missed for a few frames keeps its id (TrackIds) and so its verdict; after this the
  /// verdict is dropped, so memory follows the faces around, not the run's length. Face ids are
  /// not reused within TransientIds::kRepeatWindow ids, so a dropped verdict is never wanted again
  /// in practice.
  static constexpr double kVerdictMemory_s = 60.0;

  CandidateMatcher(const MatcherConfig& config, core::Rng rng) : config_(config), rng_(rng) {}

  /// This frame's matches. Sim time going backwards (a world reset) forgets every verdict.
  std::vector<CandidateMatch> update(const PerceptionFrame& frame);

  /// Face ids whose verdict is remembered.
  size_t remembered_count() const { return recognised_.size(); }

 private:
  struct Verdict {
    bool recognised{false};
    double last_seen_s{0.0};
  };

  void send(std::vector<CandidateMatch>& matches, CandidateMatch match) const;
  double noisy(double confidence);

  MatcherConfig config_;
  core::Rng rng_;
  std::unordered_map<std::string, Verdict> recognised_;  ///< By face id.
};

}  // namespace ari_social_sim::perception
