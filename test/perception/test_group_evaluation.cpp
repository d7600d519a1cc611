#include <gtest/gtest.h>

#include <string>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/perception/group_evaluation.hpp"

namespace ari_social_sim::perception {
namespace {

TEST(ScoreFrame, ExactMatchIsPerfect) {
  const FrameScore score =
      score_frame({{"a", "b"}, {"c", "d", "e"}}, {{"e", "c", "d"}, {"b", "a"}}, kMatchAll);
  EXPECT_EQ(score.true_positives, 2u);
  EXPECT_DOUBLE_EQ(score.precision, 1.0);
  EXPECT_DOUBLE_EQ(score.recall, 1.0);
}

TEST(ScoreFrame, TwoThirdsOfTheLargerGroupIsAMatch) {
  // Detected {a,b,c} vs true {a,b}: 2 shared / max(3,2) = 2/3.
  const FrameScore two_thirds = score_frame({{"a", "b", "c"}}, {{"a", "b"}}, kMatchTwoThirds);
  EXPECT_EQ(two_thirds.true_positives, 1u);
  EXPECT_DOUBLE_EQ(two_thirds.precision, 1.0);
  // The same pair does not match under T = 1: TP 0 of 1 detected, 0 of 1 true.
  const FrameScore all = score_frame({{"a", "b", "c"}}, {{"a", "b"}}, kMatchAll);
  EXPECT_EQ(all.true_positives, 0u);
  EXPECT_EQ(all.false_positives(), 1u);
  EXPECT_EQ(all.false_negatives(), 1u);
  EXPECT_DOUBLE_EQ(all.precision, 0.0);
  EXPECT_DOUBLE_EQ(all.recall, 0.0);
  // Detected {a,b,c,d} vs true {a,b}: 2/4 < 2/3.
  EXPECT_EQ(score_frame({{"a", "b", "c", "d"}}, {{"a", "b"}}, kMatchTwoThirds).true_positives, 0u);
}

TEST(ScoreFrame, SingletonsAreDroppedFromBothSides) {
  const FrameScore score = score_frame({{"x"}, {"a", "b"}}, {{"a", "b"}, {"y"}}, kMatchAll);
  EXPECT_EQ(score.detected, 1u);
  EXPECT_EQ(score.truth, 1u);
  EXPECT_DOUBLE_EQ(score.precision, 1.0);
  EXPECT_DOUBLE_EQ(score.recall, 1.0);
}

TEST(ScoreFrame, MixedFrame) {
  // True {a,b} found exactly, {c,d,x} found by {c,d} (2/3); {e,f} is a false positive:
  // P = 2/3, R = 2/2.
  const FrameScore score = score_frame({{"a", "b"}, {"c", "d"}, {"e", "f"}},
                                       {{"a", "b"}, {"c", "d", "x"}}, kMatchTwoThirds);
  EXPECT_EQ(score.true_positives, 2u);
  EXPECT_EQ(score.false_positives(), 1u);
  EXPECT_EQ(score.false_negatives(), 0u);
  EXPECT_DOUBLE_EQ(score.precision, 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(score.recall, 1.0);
}

TEST(ScoreFrame, DegenerateFrames) {
  // Nothing detected, nothing to find: P = R = 1.
  FrameScore score = score_frame({}, {{"a"}}, kMatchTwoThirds);
  EXPECT_DOUBLE_EQ(score.precision, 1.0);
  EXPECT_DOUBLE_EQ(score.recall, 1.0);
  // Nothing detected, one group to find: P = 1, R = 0.
  score = score_frame({{"a"}}, {{"a", "b"}}, kMatchTwoThirds);
  EXPECT_DOUBLE_EQ(score.precision, 1.0);
  EXPECT_DOUBLE_EQ(score.recall, 0.0);
  // A group detected, nothing to find: P = 0, R = 1.
  score = score_frame({{"a", "b"}}, {}, kMatchTwoThirds);
  EXPECT_DOUBLE_EQ(score.precision, 0.0);
  EXPECT_DOUBLE_EQ(score.recall, 1.0);
}

TEST(ScoreFrame, ThresholdMustBeAboveOneHalf) {
  try {
    score_frame({}, {}, 0.5);
    FAIL() << "no ConfigError";
  } catch (const core::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("threshold"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("(0.5, 1]"), std::string::npos) << e.what();
  }
  EXPECT_THROW(score_frame({}, {}, 1.01), core::ConfigError);
}

TEST(EvaluateGroups, AveragesPerFrameScoresOverAnnotatedFrames) {
  // Frame 1: group missed (P 1, R 0). Frame 2: found (1, 1). Frame 3: in neither table (1, 1).
  // Frame 4: false alarm (0, 1). Frame 5 is detected but not annotated, so ignored.
  const GroupTable detected{{2, {{"a", "b"}}}, {4, {{"c", "d"}}}, {5, {{"e", "f"}}}};
  const GroupTable truth{{1, {{"a", "b"}}}, {2, {{"a", "b"}}}};
  const EvaluationScore score = evaluate_groups(detected, truth, {1, 2, 3, 4}, kMatchTwoThirds);
  EXPECT_EQ(score.frames, 4u);
  EXPECT_DOUBLE_EQ(score.precision, 3.0 / 4.0);  // (1 + 1 + 1 + 0) / 4
  EXPECT_DOUBLE_EQ(score.recall, 3.0 / 4.0);     // (0 + 1 + 1 + 1) / 4
  EXPECT_DOUBLE_EQ(score.f1, 0.75);              // 2 PR / (P + R) with P = R
  EXPECT_EQ(score.true_positives, 1u);
  EXPECT_EQ(score.false_positives, 1u);
  EXPECT_EQ(score.false_negatives, 1u);
}

TEST(EvaluateGroups, F1ComesFromTheMeans) {
  // Frame 1: P 1, R 0; frame 2: P 1, R 1. Means 1 and 0.5: F1 = 2 * 0.5 / 1.5 = 2/3 (the mean of
  // the per-frame F1s would be 0.5).
  const GroupTable detected{{2, {{"a", "b"}}}};
  const GroupTable truth{{1, {{"a", "b"}}}, {2, {{"a", "b"}}}};
  const EvaluationScore score = evaluate_groups(detected, truth, {1, 2}, kMatchAll);
  EXPECT_DOUBLE_EQ(score.precision, 1.0);
  EXPECT_DOUBLE_EQ(score.recall, 0.5);
  EXPECT_DOUBLE_EQ(score.f1, 2.0 / 3.0);
}

TEST(EvaluateGroups, NoFramesIsAnError) {
  EXPECT_THROW(evaluate_groups({}, {}, {}, kMatchAll), core::ConfigError);
}

}  // namespace
}  // namespace ari_social_sim::perception
