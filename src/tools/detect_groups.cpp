// detect_groups: runs the GCFF F-formation detector over a recorded data set (CSV), and optionally
// scores it against ground truth with the protocol of GCFF's evaluation code (Setti 2015).
// Standard output gets the groups of every frame (or the score) or nothing: SIGINT or SIGTERM
// stops between two frames, writes nothing and exits with 128 + the signal's number.

#include <cstdio>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "ari_social_sim/core/command_line.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/stop_signal.hpp"
#include "ari_social_sim/perception/fformation_dataset.hpp"
#include "ari_social_sim/perception/gcff.hpp"
#include "ari_social_sim/perception/group_evaluation.hpp"

namespace {

using namespace ari_social_sim;

constexpr int kUsageError = 2;

constexpr const char* kUsage = R"(Usage:
  detect_groups --features FEATURES_CSV --stride S --mdl M
                [--evaluate GROUNDTRUTH_CSV --frames FRAMES_CSV [--threshold 2/3|1]]

Detects F-formations (conversational groups) frame by frame with GCFF.

  --features FILE   people per frame: header "frame,person_id,x,y,theta", positions in any
                    length unit, theta in rad counter-clockwise from +x (the body's facing).
  --stride S        distance from a person to their candidate o-space centre, in the unit of
                    the positions (> 0), e.g. 0.5 for metres, 50 for centimetres.
  --mdl M           cost of one more group, in that unit squared (> 0), e.g. 0.8 m^2, 8000 cm^2.

Without --evaluate, writes the groups (two or more people) as CSV to standard output:
"frame,group,person_id", one row per member; frames and person ids are copied unchanged,
groups are numbered 0, 1, ... within each frame.

  --evaluate FILE   ground-truth groups, header "frame,group,person_id": print instead one line
                    "precision P recall R f1 F" (means of per-frame precision and recall over
                    the annotated frames, F1 from the means).
  --frames FILE     the annotated frames, header "frame" (required with --evaluate).
  --threshold T     a group is found when it shares >= T of the larger of the two groups'
                    members: 2/3 (default) or 1.
  --help            print this text.

SIGINT (Ctrl-C) or SIGTERM stops the detection between two frames and writes nothing: standard
output gets the groups of every frame, or the score, or nothing. A second Ctrl-C kills at once.

Exit status: 0 on success, 2 on bad arguments or unreadable or malformed files, 1 when the
output cannot be written, 130 after SIGINT and 143 after SIGTERM.
)";

// Any finite positive number: the unit is the data set's.
const core::NumberOption kStride{"--stride", core::positive()};
const core::NumberOption kMdl{"--mdl", core::positive()};

struct Options {
  std::string features;
  std::optional<double> stride;
  std::optional<double> mdl;
  std::string ground_truth;
  std::string frames;
  double threshold{perception::kMatchTwoThirds};
};

double parse_threshold(const std::string& text) {
  if (text == "2/3") {
    return perception::kMatchTwoThirds;
  }
  if (text == "1") {
    return perception::kMatchAll;
  }
  throw core::ConfigError("--threshold: expected 2/3 or 1, got \"" + text + "\"");
}

// Returns nothing when --help was asked for.
std::optional<Options> parse_options(int argc, char** argv) {
  Options options;
  bool threshold_given = false;
  for (int a = 1; a < argc; ++a) {
    const std::string option = argv[a];
    if (option == "--help" || option == "-h") {
      return std::nullopt;
    }
    const bool known = option == "--features" || option == "--stride" || option == "--mdl" ||
                       option == "--evaluate" || option == "--frames" || option == "--threshold";
    if (!known) {
      throw core::ConfigError("unknown option \"" + option + "\"");
    }
    const std::string value = core::option_value(argc, argv, a);
    if (option == "--features") {
      options.features = value;
    } else if (option == "--stride") {
      options.stride = kStride.parse(value);
    } else if (option == "--mdl") {
      options.mdl = kMdl.parse(value);
    } else if (option == "--evaluate") {
      options.ground_truth = value;
    } else if (option == "--frames") {
      options.frames = value;
    } else if (option == "--threshold") {
      options.threshold = parse_threshold(value);
      threshold_given = true;
    }
  }
  if (options.features.empty() || !options.stride || !options.mdl) {
    throw core::ConfigError("--features, --stride and --mdl are required");
  }
  if (options.ground_truth.empty() != options.frames.empty()) {
    throw core::ConfigError("--evaluate and --frames go together");
  }
  if (threshold_given && options.ground_truth.empty()) {
    throw core::ConfigError("--threshold needs --evaluate");
  }
  core::check_input_file("--features", options.features);
  if (!options.ground_truth.empty()) {
    core::check_input_file("--evaluate", options.ground_truth);
    core::check_input_file("--frames", options.frames);
  }
  return options;
}

// Throws core::Error when standard output takes less than everything (a full disk, a closed pipe).
void write_groups(const perception::GroupTable& detected) {
  std::string out = "frame,group,person_id\n";
  for (const auto& [frame, groups] : detected) {
    for (size_t g = 0; g < groups.size(); ++g) {
      for (const std::string& person : groups[g]) {
        out += std::to_string(frame) + "," + std::to_string(g) + "," + person + "\n";
      }
    }
  }
  if (std::fwrite(out.data(), 1, out.size(), stdout) != out.size() || std::fflush(stdout) != 0) {
    throw core::Error("standard output: writing the groups failed");
  }
}

// After a stop signal: nothing was written. Returns the exit code.
int report_stop(size_t frames_done, size_t frames) {
  const int signal = core::g_stop_signal;
  std::cerr << "detect_groups: interrupted by " << core::stop_signal_name(signal) << " after "
            << frames_done << " of " << frames
            << " frames: nothing written (standard output gets every frame's result or none); "
               "rerun to detect them all\n";
  return core::stopped_exit_code(signal);
}

int run(const Options& options) {
  perception::GcffParams params;
  params.stride = *options.stride;
  params.mdl = *options.mdl;
  params.validate();
  // Every input is read before the detection, so that a bad file fails before any output.
  const perception::FeatureTable features = perception::read_fformation_features(options.features);
  perception::GroupTable truth;
  std::vector<perception::FrameId> frames;
  if (!options.ground_truth.empty()) {
    truth = perception::read_fformation_groups(options.ground_truth);
    frames = perception::read_fformation_frames(options.frames);
  }

  const perception::GroupTable detected = perception::detect_fformation_groups(
      features, params, [] { return core::g_stop_signal != 0; });
  // A signal after the last frame stops nothing: the result is complete and written.
  if (detected.size() < features.size()) {
    return report_stop(detected.size(), features.size());
  }
  if (options.ground_truth.empty()) {
    write_groups(detected);
    return 0;
  }
  const perception::EvaluationScore score =
      perception::evaluate_groups(detected, truth, frames, options.threshold);
  if (std::printf("precision %.3f recall %.3f f1 %.3f\n", score.precision, score.recall, score.f1) <
          0 ||
      std::fflush(stdout) != 0) {
    throw core::Error("standard output: writing the score failed");
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const std::optional<Options> options = parse_options(argc, argv);
    if (!options) {
      std::cout << kUsage;
      return 0;
    }
    core::install_stop_handler();
    return run(*options);
  } catch (const core::ConfigError& e) {
    std::cerr << "detect_groups: " << e.what() << "\n(see detect_groups --help)\n";
    return kUsageError;
  } catch (const core::Error& e) {
    std::cerr << "detect_groups: " << e.what() << "\n";
    return 1;
  }
}
