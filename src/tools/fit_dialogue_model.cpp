// fit_dialogue_model: fits P(user act | context) per role to the MPGT corpus and writes the
// user model YAML the dialogue simulation loads (config/dialogue/mpgt_user_model.yaml).
//
//   fit_dialogue_model [--corpus DIR] [--out FILE] [--min-row-count N] [--prior-weight W]
//
// --corpus defaults to the build-time ARI_MPGT_DIR, <source>/../shared/dialogue/mpgt.
// Without --out the model goes to stdout. Exit code 2 on bad input, with the reason on stderr.
#include <fstream>
#include <iostream>
#include <string>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/dialogue/model_fitting.hpp"

namespace {

using namespace ari_social_sim;

void print_usage() {
  std::cerr << "usage: fit_dialogue_model [--corpus DIR] [--out FILE] [--min-row-count N] "
               "[--prior-weight W]\n"
            << "  --corpus defaults to " << dialogue::default_mpgt_dir() << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  std::string corpus_dir = dialogue::default_mpgt_dir();
  std::string out_path;
  dialogue::FitOptions options;
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string arg = argv[i];
      if (arg == "--help" || arg == "-h") {
        print_usage();
        return 0;
      }
      if (i + 1 >= argc) {
        throw core::ConfigError("command line: " + arg + ": expected a value after it");
      }
      const std::string value = argv[++i];
      if (arg == "--corpus") {
        corpus_dir = value;
      } else if (arg == "--out") {
        out_path = value;
      } else if (arg == "--min-row-count") {
        options.min_row_count = static_cast<unsigned>(std::stoul(value));
      } else if (arg == "--prior-weight") {
        options.prior_weight = std::stod(value);
      } else {
        throw core::ConfigError("command line: unknown option " + arg);
      }
    }
    const dialogue::MpgtCorpus corpus = dialogue::load_mpgt_corpus(corpus_dir);
    const dialogue::UserModel model = dialogue::fit_user_model(corpus, options);
    if (out_path.empty()) {
      model.write(std::cout);
    } else {
      std::ofstream out(out_path);
      if (!out) {
        throw core::ConfigError(out_path + ": cannot write the file");
      }
      model.write(out);
    }
    std::cerr << "fitted " << model.roles.size() << " roles on " << corpus.dialogues.size()
              << " conversations (" << corpus.utterance_count() << " utterances, "
              << corpus.act_repairs << " acts with repaired brackets, "
              << corpus.skipped_goal_labels << " unreadable goal labels)\n";
  } catch (const core::Error& e) {
    std::cerr << e.what() << "\n";
    return 2;
  } catch (const std::logic_error& e) {
    std::cerr << "command line: expected a number: " << e.what() << "\n";
    print_usage();
    return 2;
  }
  return 0;
}
