// Reproduces the reference scores of GCFF on the development sets in shared/fformation
// (README.md there; specs/algorithms.md 1.7): positions in cm, the parameters published with
// the data, per-frame means of precision and recall.

#include <gtest/gtest.h>

#include <string>

#include "ari_social_sim/perception/fformation_dataset.hpp"
#include "ari_social_sim/perception/gcff.hpp"
#include "ari_social_sim/perception/group_evaluation.hpp"

namespace ari_social_sim::perception {
namespace {

constexpr double kTolerance = 0.01;

struct ReferenceSet {
  std::string name;
  double stride_cm;
  double mdl_cm2;
};

const ReferenceSet kSynth{"Synth", 30.0, 6000.0};
const ReferenceSet kCoffeeBreak1{"CoffeeBreak_Seq1", 50.0, 8000.0};
const ReferenceSet kCoffeeBreak2{"CoffeeBreak_Seq2", 20.0, 7000.0};

std::string data_file(const ReferenceSet& set, const std::string& kind) {
  return std::string(ARI_FFORMATION_DIR) + "/" + set.name + "_" + kind + ".csv";
}

// Detections and ground truth of one set, read once.
struct LoadedSet {
  GroupTable detected;
  GroupTable truth;
  std::vector<FrameId> frames;
};

LoadedSet load_and_detect(const ReferenceSet& set) {
  GcffParams params;
  params.stride = set.stride_cm;
  params.mdl = set.mdl_cm2;
  LoadedSet loaded;
  loaded.detected =
      detect_fformation_groups(read_fformation_features(data_file(set, "features")), params);
  loaded.truth = read_fformation_groups(data_file(set, "groups"));
  loaded.frames = read_fformation_frames(data_file(set, "frames"));
  return loaded;
}

EvaluationScore score(const ReferenceSet& set, double threshold) {
  const LoadedSet loaded = load_and_detect(set);
  return evaluate_groups(loaded.detected, loaded.truth, loaded.frames, threshold);
}

void expect_scores(const EvaluationScore& score, double precision, double recall, double f1) {
  EXPECT_NEAR(score.precision, precision, kTolerance);
  EXPECT_NEAR(score.recall, recall, kTolerance);
  EXPECT_NEAR(score.f1, f1, kTolerance);
}

TEST(GcffReference, SynthTwoThirds) {
  const EvaluationScore result = score(kSynth, kMatchTwoThirds);
  EXPECT_EQ(result.frames, 100u);
  expect_scores(result, 0.967, 0.980, 0.973);
}

TEST(GcffReference, SynthAll) {
  expect_scores(score(kSynth, kMatchAll), 0.908, 0.910, 0.909);
}

TEST(GcffReference, CoffeeBreakSeq1TwoThirds) {
  const EvaluationScore result = score(kCoffeeBreak1, kMatchTwoThirds);
  EXPECT_EQ(result.frames, 45u);
  expect_scores(result, 0.749, 0.793, 0.770);
}

TEST(GcffReference, CoffeeBreakSeq1All) {
  expect_scores(score(kCoffeeBreak1, kMatchAll), 0.441, 0.461, 0.451);
}

TEST(GcffReference, CoffeeBreakSeq2TwoThirds) {
  const EvaluationScore result = score(kCoffeeBreak2, kMatchTwoThirds);
  EXPECT_EQ(result.frames, 74u);
  expect_scores(result, 0.913, 0.979, 0.944);
}

TEST(GcffReference, CoffeeBreakSeq2All) {
  expect_scores(score(kCoffeeBreak2, kMatchAll), 0.711, 0.753, 0.731);
}

// Both sequences as one set of 119 frames: per-frame means weighted by frame count, F1 from them.
// The published GCFF result is 0.85 / 0.91 / 0.88 (T = 2/3).
TEST(GcffReference, CoffeeBreakBothSequences) {
  for (const auto& [threshold, expected] :
       {std::pair<double, EvaluationScore>{kMatchTwoThirds, {119, 0.851, 0.908, 0.879}},
        std::pair<double, EvaluationScore>{kMatchAll, {119, 0.609, 0.643, 0.625}}}) {
    const EvaluationScore first = score(kCoffeeBreak1, threshold);
    const EvaluationScore second = score(kCoffeeBreak2, threshold);
    EvaluationScore both;
    both.frames = first.frames + second.frames;
    both.precision = (first.precision * first.frames + second.precision * second.frames) /
                     static_cast<double>(both.frames);
    both.recall = (first.recall * first.frames + second.recall * second.frames) /
                  static_cast<double>(both.frames);
    both.f1 = 2.0 * both.precision * both.recall / (both.precision + both.recall);
    EXPECT_EQ(both.frames, expected.frames);
    expect_scores(both, expected.precision, expected.recall, expected.f1);
  }
}

}  // namespace
}  // namespace ari_social_sim::perception
