// fit_dialogue_model: fits P(user act | context) per role to the MPGT corpus and writes the
// user model YAML the dialogue simulation loads (config/dialogue/mpgt_user_model.yaml).
//
//   fit_dialogue_model [--corpus DIR] [--out FILE [--overwrite]] [--min-row-count N]
//                      [--prior-weight W]
//
// --corpus is the MPGT corpus's folder, by default $ARI_MPGT_DIR, else the data set's folder
// that scripts/fetch_data.sh fills (docs/dialogue.md); without any, it says how to get it.
// Without --out the model goes to stdout; an existing --out is replaced only with --overwrite,
// and only once the model is complete. SIGINT or SIGTERM stops between loading, fitting and
// writing, writes nothing and exits with 128 + the signal's number: the whole fit of MPGT's 29
// conversations takes well under a second, so its phases are the units of work. Exit code 2 on
// bad input, with the reason on stderr; 1 when writing fails.
#include <iostream>
#include <optional>
#include <string>

#include "ari_social_sim/core/command_line.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/output_file.hpp"
#include "ari_social_sim/core/stop_signal.hpp"
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
            << "  --out appears only when the model is complete; SIGINT (Ctrl-C) or SIGTERM stops\n"
            << "    the fit and writes nothing (a second Ctrl-C kills at once)\n"
            << "  exit status: 0 on success, 2 on bad input, 1 when writing fails, 130 after\n"
            << "    SIGINT and 143 after SIGTERM\n"
            << dialogue::mpgt_corpus_help();
}

struct Options {
  std::string corpus_dir;
  std::string out_path;
  bool overwrite{false};
  dialogue::FitOptions fit;
};

// The checked command line; nothing when --help was asked for. Throws core::ConfigError.
std::optional<Options> parse_options(int argc, char** argv) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      return std::nullopt;
    }
    if (arg == "--overwrite") {
      options.overwrite = true;
      continue;
    }
    core::check_known_option(arg, {"--corpus", "--out", "--min-row-count", "--prior-weight",
                                   "--overwrite", "--help", "-h"});
    const std::string value = core::option_value(argc, argv, i);
    if (arg == "--corpus") {
      options.corpus_dir = value;
    } else if (arg == "--out") {
      options.out_path = value;
    } else if (arg == "--min-row-count") {
      options.fit.min_row_count = static_cast<unsigned>(kMinRowCount.parse(value));
    } else {
      options.fit.prior_weight = kPriorWeight.parse(value);  // --prior-weight
    }
  }
  if (options.overwrite && options.out_path.empty()) {
    throw core::ConfigError("--overwrite: expected --out too (standard output is not replaced)");
  }
  if (!options.out_path.empty()) {
    core::check_output_file("--out", options.out_path, options.overwrite);
  }
  options.corpus_dir = dialogue::required_mpgt_dir(options.corpus_dir, "the fit");
  return options;
}

// After a stop signal: nothing was written. Returns the exit code.
int report_stop(const std::string& done) {
  const int signal = core::g_stop_signal;
  std::cerr << "fit_dialogue_model: interrupted by " << core::stop_signal_name(signal) << " after "
            << done << ": nothing written (the model is written whole or not at all); rerun to "
            << "fit it\n";
  return core::stopped_exit_code(signal);
}

// Fits the model and writes it to --out or standard output: 0, or the exit code of report_stop
// when a stop signal came first. Throws core::Error when writing fails.
int fit_and_write(const Options& options, const dialogue::MpgtCorpus& corpus) {
  const dialogue::UserModel model = dialogue::fit_user_model(corpus, options.fit);
  if (core::g_stop_signal != 0) {
    return report_stop("fitting the model, before writing it");
  }
  if (options.out_path.empty()) {
    model.write(std::cout);
    std::cout.flush();
    if (!std::cout) {
      throw core::Error("standard output: writing the model failed");
    }
  } else {
    core::OutputFile out("--out", options.out_path);
    model.write(out.stream());
    out.commit();
  }
  std::cerr << "fitted " << model.roles.size() << " roles on " << corpus.dialogues.size()
            << " conversations (" << corpus.utterance_count() << " utterances, "
            << corpus.act_repairs << " acts with repaired brackets, " << corpus.skipped_goal_labels
            << " unreadable goal labels)\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::optional<Options> options;
  try {
    options = parse_options(argc, argv);
  } catch (const core::Error& e) {
    std::cerr << "fit_dialogue_model: " << e.what() << "\n";
    print_usage();
    return 2;
  }
  if (!options) {
    print_usage();
    return 0;
  }
  core::install_stop_handler();
  dialogue::MpgtCorpus corpus;
  try {
    corpus = dialogue::load_mpgt_corpus(options->corpus_dir);
  } catch (const core::Error& e) {
    std::cerr << "fit_dialogue_model: " << e.what() << "\n";
    print_usage();
    return 2;
  }
  if (core::g_stop_signal != 0) {
    return report_stop("loading " + std::to_string(corpus.dialogues.size()) + " conversations");
  }
  try {
    return fit_and_write(*options, corpus);
  } catch (const core::Error& e) {
    std::cerr << "fit_dialogue_model: " << e.what() << "\n";
    return 1;
  }
}
