// fit_dialogue_model: fits P(user act | context) per role to the MPGT corpus and writes the
// user model YAML the dialogue simulation loads (config/dialogue/mpgt_user_model.yaml).
//
//   fit_dialogue_model [--corpus DIR] [--out FILE [--overwrite]] [--min-row-count N]
//                      [--prior-weight W]
//
// --corpus is the MPGT corpus's folder, by default $ARI_MPGT_DIR, else the data set's folder
// that scripts/fetch_data.sh fills (docs/dialogue.md); without any, it says how to get it.
// Without --out the model goes to stdout; an existing --out is replaced only with --overwrite,
// and only once the model is complete. Exit code 2 on bad input, with the reason on stderr; 1
// when writing fails.
#include <iostream>
#include <string>

#include "ari_social_sim/core/command_line.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/output_file.hpp"
#include "ari_social_sim/dialogue/model_fitting.hpp"

namespace {

using namespace ari_social_sim;

// The documented ranges (README, docs/dialogue.md). MPGT has under 800 utterances, so a row
// count above 100 000 would send every context to the marginal row; a prior above 10^6
// pseudo-counts drowns any corpus.
constexpr core::IntegerOption kMinRowCount{"--min-row-count", 1, 100000};
const core::NumberOption kPriorWeight{"--prior-weight", core::between(0.0, 1e6)};

void print_usage() {
  std::cerr << "usage: fit_dialogue_model [--corpus DIR] [--out FILE [--overwrite]] "
               "[--min-row-count N] [--prior-weight W]\n"
            << "  N in " << kMinRowCount.range() << " (default 10), W in "
            << kPriorWeight.bounds.describe() << " (default 5)\n"
            << "  --corpus DIR: the MPGT corpus (below)\n"
            << dialogue::mpgt_corpus_help();
}

}  // namespace

int main(int argc, char** argv) {
  std::string corpus_dir;
  std::string out_path;
  bool overwrite = false;
  dialogue::FitOptions options;
  dialogue::MpgtCorpus corpus;
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string arg = argv[i];
      if (arg == "--help" || arg == "-h") {
        print_usage();
        return 0;
      }
      if (arg == "--overwrite") {
        overwrite = true;
        continue;
      }
      core::check_known_option(arg, {"--corpus", "--out", "--min-row-count", "--prior-weight",
                                     "--overwrite", "--help", "-h"});
      const std::string value = core::option_value(argc, argv, i);
      if (arg == "--corpus") {
        corpus_dir = value;
      } else if (arg == "--out") {
        out_path = value;
      } else if (arg == "--min-row-count") {
        options.min_row_count = static_cast<unsigned>(kMinRowCount.parse(value));
      } else {
        options.prior_weight = kPriorWeight.parse(value);  // --prior-weight
      }
    }
    if (overwrite && out_path.empty()) {
      throw core::ConfigError("--overwrite: expected --out too (standard output is not replaced)");
    }
    if (!out_path.empty()) {
      core::check_output_file("--out", out_path, overwrite);
    }
    corpus_dir = dialogue::required_mpgt_dir(corpus_dir, "the fit");
    corpus = dialogue::load_mpgt_corpus(corpus_dir);
  } catch (const core::Error& e) {
    std::cerr << "fit_dialogue_model: " << e.what() << "\n";
    print_usage();
    return 2;
  }
  try {
    const dialogue::UserModel model = dialogue::fit_user_model(corpus, options);
    if (out_path.empty()) {
      model.write(std::cout);
      std::cout.flush();
      if (!std::cout) {
        throw core::Error("standard output: writing the model failed");
      }
    } else {
      core::OutputFile out("--out", out_path);
      model.write(out.stream());
      out.commit();
    }
    std::cerr << "fitted " << model.roles.size() << " roles on " << corpus.dialogues.size()
              << " conversations (" << corpus.utterance_count() << " utterances, "
              << corpus.act_repairs << " acts with repaired brackets, "
              << corpus.skipped_goal_labels << " unreadable goal labels)\n";
  } catch (const core::Error& e) {
    std::cerr << "fit_dialogue_model: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
