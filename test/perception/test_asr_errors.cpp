#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "ari_social_sim/perception/asr_errors.hpp"

namespace ari_social_sim::perception {
namespace {

// Minimum numbers of substitutions, deletions and insertions turning `reference` into
// `hypothesis` (Levenshtein alignment over words), as a WER scorer counts them.
struct EditCounts {
  int substitutions{0};
  int deletions{0};
  int insertions{0};
  int total() const { return substitutions + deletions + insertions; }
};

EditCounts align(const std::vector<std::string>& reference,
                 const std::vector<std::string>& hypothesis) {
  const size_t n = reference.size(), m = hypothesis.size();
  std::vector<std::vector<EditCounts>> best(n + 1, std::vector<EditCounts>(m + 1));
  for (size_t i = 1; i <= n; ++i) {
    best[i][0] = best[i - 1][0];
    ++best[i][0].deletions;
  }
  for (size_t j = 1; j <= m; ++j) {
    best[0][j] = best[0][j - 1];
    ++best[0][j].insertions;
  }
  for (size_t i = 1; i <= n; ++i) {
    for (size_t j = 1; j <= m; ++j) {
      EditCounts diagonal = best[i - 1][j - 1];
      diagonal.substitutions += reference[i - 1] == hypothesis[j - 1] ? 0 : 1;
      EditCounts deletion = best[i - 1][j];
      ++deletion.deletions;
      EditCounts insertion = best[i][j - 1];
      ++insertion.insertions;
      best[i][j] =
          std::min({diagonal, deletion, insertion},
                   [](const EditCounts& a, const EditCounts& b) { return a.total() < b.total(); });
    }
  }
  return best[n][m];
}

std::vector<std::string> transcribe(AsrErrors& asr, const std::vector<std::string>& words) {
  std::vector<std::string> transcript;
  for (const std::string& word : words) {
    asr.hear(word, transcript);
  }
  return transcript;
}

TEST(AsrErrors, WithoutErrorsTheTranscriptIsTheUtterance) {
  SpeechErrors errors;
  errors.word_error_rate = 0.0;
  AsrErrors asr(errors, core::Rng(1));
  const std::vector<std::string> words = split_words("  where is  the\tradiology room ");
  EXPECT_EQ(words, (std::vector<std::string>{"where", "is", "the", "radiology", "room"}));
  EXPECT_EQ(transcribe(asr, words), words);
  EXPECT_EQ(join_words(words), "where is the radiology room");
}

// Must-show 3: the word error rate measured by aligning transcripts with what was said is within
// 10 % (relative) of the configured one.
TEST(AsrErrors, MeasuredWordErrorRateMatchesTheConfiguredOne) {
  SpeechErrors errors;
  errors.word_error_rate = 0.15;
  errors.substitution_share = 0.5;
  errors.deletion_share = 0.3;
  errors.insertion_share = 0.2;
  AsrErrors asr(errors, core::Rng(77));
  const std::vector<std::string> utterance =
      split_words("good morning could you tell me where the radiology department is please");
  EditCounts sum;
  int words = 0;
  for (int i = 0; i < 20000; ++i) {
    const EditCounts counts = align(utterance, transcribe(asr, utterance));
    sum.substitutions += counts.substitutions;
    sum.deletions += counts.deletions;
    sum.insertions += counts.insertions;
    words += static_cast<int>(utterance.size());
  }
  const double wer = static_cast<double>(sum.total()) / words;
  // An alignment merges a deletion and an insertion next to it into one substitution, so the
  // measured rate is slightly below the drawn one (by about 2 P(D) P(I) = 0.0027 per word), and
  // so are the deletion and insertion rates (by 9 % here); the total is what a scorer reports.
  EXPECT_NEAR(wer, 0.15, 0.015);
  std::printf("[ measured ] WER %.4f (configured 0.15): S %.4f D %.4f I %.4f over %d words\n", wer,
              static_cast<double>(sum.substitutions) / words,
              static_cast<double>(sum.deletions) / words,
              static_cast<double>(sum.insertions) / words, words);
}

TEST(AsrErrors, SubstitutesAreOtherVocabularyWords) {
  SpeechErrors errors;
  errors.word_error_rate = 1.0;
  errors.substitution_share = 1.0;
  errors.deletion_share = 0.0;
  errors.insertion_share = 0.0;
  errors.vocabulary = {"yes", "no"};
  AsrErrors asr(errors, core::Rng(3));
  for (int i = 0; i < 100; ++i) {
    EXPECT_EQ(transcribe(asr, {"yes", "no", "maybe"})[0], "no");
  }
  EXPECT_EQ(transcribe(asr, {"yes", "no"}), (std::vector<std::string>{"no", "yes"}));
}

}  // namespace
}  // namespace ari_social_sim::perception
