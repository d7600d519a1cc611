// Stock OpenCV detectors on the head camera's images of the shipped scenarios, as a user gets them
// (docs/cameras.md, "Stock detectors in the shipped scenarios"): each scenario's episodes run in
// process and the head camera renders them with the camera effects, as export_dataset does. On
// every frame: HOG people detection at native resolution (as OpenCV's C++ and Python samples run
// it) and at 0.35 of it, the two frontal face cascades (alt2 and default) and the profile
// cascade, the cascades on the image and on its histogram-equalised copies: global
// (cv::equalizeHist, the usual first step before a cascade) and local (CLAHE, clip limit 2 on 8 x 8
// tiles, the values of OpenCV's tutorial). Scored against the images' labels: recall overall and by
// skin tone (faces cut by the image's border left out), false detections on turned heads (frames
// whose faces all turn more than 45 degrees, the boxes among them that match a face, and frames
// whose faces all turn more than 60) and in frames that show nobody, and how often each frontal
// cascade fires on a face as the face turns from the camera. Prints Markdown tables.
//
// usage: detector_study [--frames N] [--every SECONDS] [--episode-frames N] [--scenarios a,b,...]
//                       [--misses DIR] [--faces-only]
//   --frames: frames per scenario (default 210: 1,050 over the five shipped scenarios)
//   --every: sim seconds between frames (default 1.0)
//   --episode-frames: at most this many frames of one episode (default 50), so that each
//                     scenario's frames come from several seeds (1, 2, ...)
//   --misses: write a crop of each face a frontal cascade misses on the image as it is into DIR
//             (which must exist), named by scenario, seed, sim time, person, skin tone and
//             cascade; and a crop of each frontal detection on a turned head ("false_...", with
//             the preprocessing, "_equalizeHist" or "_CLAHE", when not the image as it is, and
//             the turn of the face under it)
//   --faces-only: the face cascades alone, without HOG (about 2 s a frame at native resolution),
//                 to measure a change to the faces quickly

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/objdetect.hpp>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "../test/common/detector_scoring.hpp"
#include "ari_social_sim/core/bounds.hpp"
#include "ari_social_sim/core/command_line.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/engine/episode.hpp"
#include "ari_social_sim/rendering/camera_rig.hpp"
#include "ari_social_sim/rendering/snapshot_cameras.hpp"
#include "ari_social_sim/scenario/scenario.hpp"

namespace {

using namespace ari_social_sim;
using namespace ari_social_sim::rendering::detector_scoring;
using rendering::PersonLabel;

constexpr double kHogScale = 0.35;  // test_detector_study's scale (docs/cameras.md)
constexpr int kSkinTones = 6;
// The frontal cascades' recall counts faces within kFrontalWithinDeg of the camera; their false
// detections are counted in frames where every face is turned more than kEveryFaceTurnedDeg.
// Faces turned kTurnedPastFrontalDeg or more (up to 90) are the profile cascade's; a frontal
// window on such a head is false wherever it lies, and the frames where every face is the profile
// cascade's are counted apart: a face turned 45 to 60 degrees still shows both eyes.
constexpr double kFrontalWithinDeg = 25.0;
constexpr double kEveryFaceTurnedDeg = 45.0;
constexpr double kTurnedPastFrontalDeg = 60.0;
// The turns the frontal cascades' curve counts faces in, bounds of its bins (labels give a face
// box to faces turned less than 90 degrees only).
constexpr std::array<double, 8> kTurnBinsDeg = {0, 15, 25, 35, 45, 55, 65, 90};
constexpr int kTurnBins = static_cast<int>(kTurnBinsDeg.size()) - 1;
// What the cascades run on: the grey image as it is, equalised globally, equalised locally.
constexpr int kPreprocessings = 3;
constexpr const char* kPreprocessingNames[kPreprocessings] = {"", ", equalizeHist", ", CLAHE"};
constexpr const char* kPreprocessingTags[kPreprocessings] = {"", "_equalizeHist", "_CLAHE"};

struct Options {
  int frames_per_scenario{210};
  double every_s{1.0};
  int frames_per_episode{50};
  std::vector<std::string> scenarios{"corridor", "group_discussion", "join_conversation",
                                     "join_group", "waiting_room"};
  std::string misses_dir;  // empty: no crops
  bool faces_only{false};
};

[[noreturn]] void usage(const std::string& problem) {
  std::fprintf(stderr,
               "detector_study: %s\nusage: detector_study [--frames N] [--every SECONDS] "
               "[--episode-frames N] [--scenarios a,b,...] [--misses DIR] [--faces-only]\n",
               problem.c_str());
  std::exit(2);
}

const core::NumberOption kFrames{"--frames", core::between(1, 100000)};
const core::NumberOption kEvery{"--every", core::between(0.05, 60.0)};
const core::NumberOption kEpisodeFrames{"--episode-frames", core::between(1, 100000)};

// Throws core::ConfigError naming the option and what it expects.
Options parse(int argc, char** argv) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    const std::string option = argv[i];
    if (option == "--faces-only") {
      options.faces_only = true;
      continue;
    }
    const std::string value = core::option_value(argc, argv, i);
    if (option == "--frames") {
      options.frames_per_scenario = static_cast<int>(kFrames.parse(value));
    } else if (option == "--every") {
      options.every_s = kEvery.parse(value);
    } else if (option == "--episode-frames") {
      options.frames_per_episode = static_cast<int>(kEpisodeFrames.parse(value));
    } else if (option == "--misses") {
      if (!std::filesystem::is_directory(value)) {
        throw core::ConfigError("--misses: expected an existing directory, got '" + value + "'");
      }
      options.misses_dir = value;
    } else if (option == "--scenarios") {
      options.scenarios.clear();
      std::stringstream list(value);
      for (std::string name; std::getline(list, name, ',');) {
        options.scenarios.push_back(name);
      }
    } else {
      throw core::ConfigError("unknown option '" + option + "'");
    }
  }
  return options;
}

// Found of total, overall and by skin tone (1 to 6).
struct Recall {
  int found{0}, total{0};
  std::array<int, kSkinTones + 1> tone_found{}, tone_total{};

  void add(const PersonLabel& label, bool hit) {
    found += hit ? 1 : 0;
    ++total;
    if (label.skin_tone >= 1 && label.skin_tone <= kSkinTones) {
      tone_found[label.skin_tone] += hit ? 1 : 0;
      ++tone_total[label.skin_tone];
    }
  }
  static double rate(int found, int total) { return total > 0 ? 100.0 * found / total : 0.0; }
};

// Detections per frame, summed over frames.
struct FalseRate {
  int detections{0}, frames{0};
  void add(int count) {
    detections += count;
    ++frames;
  }
};

// Faces with a window centred on them, of the faces in each bin of turn (kTurnBinsDeg).
struct TurnCurve {
  std::array<int, kTurnBins> found{}, total{};

  void add(double turn_deg, bool hit) {
    const auto upper = std::upper_bound(kTurnBinsDeg.begin() + 1, kTurnBinsDeg.end() - 1, turn_deg);
    const int bin = static_cast<int>(upper - kTurnBinsDeg.begin()) - 1;
    found[bin] += hit ? 1 : 0;
    ++total[bin];
  }
};

// What each face cascade found in one image, with and without equalisation.
struct FaceDetections {
  std::vector<cv::Rect> alt2, frontal_default, profile;
};

class Study {
 public:
  Study(std::string misses_dir, bool faces_only)
      : misses_dir_(std::move(misses_dir)), faces_only_(faces_only) {
    hog_.setSVMDetector(cv::HOGDescriptor::getDefaultPeopleDetector());
    load(alt2_, kFrontalAlt2Cascade);
    load(frontal_default_, kFrontalDefaultCascade);
    load(profile_, kProfileCascade);
  }

  // `frame` names the image in the crops of misses.
  void add(const cv::Mat& rgb, const std::vector<PersonLabel>& labels, const std::string& frame) {
    cv::Mat grey, equalised, local;
    cv::cvtColor(rgb, grey, cv::COLOR_RGB2GRAY);
    cv::equalizeHist(grey, equalised);
    clahe_->apply(grey, local);
    const Needs needs = needs_of(labels, grey.size());
    if (needs.hog && !faces_only_) {
      score_hog(rgb, grey, labels);
    }
    const std::array<FaceDetections, kPreprocessings> faces = {
        detect_faces(grey, needs), detect_faces(equalised, needs), detect_faces(local, needs)};
    for (int e = 0; e < kPreprocessings; ++e) {
      score_faces(faces[e], labels, grey.size(), e);
    }
    if (!misses_dir_.empty()) {
      save_frontal_misses(faces[0], labels, rgb, frame);
      for (int e = 0; e < kPreprocessings; ++e) {
        save_turned_detections(faces[e], labels, rgb, frame + kPreprocessingTags[e]);
      }
    }
    ++frames_;
  }

  void print() const;

 private:
  void print_turn_curves() const;

  static void load(cv::CascadeClassifier& cascade, const char* file) {
    if (!cascade.load(file)) {
      std::fprintf(stderr, "detector_study: cannot load %s (Debian's opencv-data)\n", file);
      std::exit(1);
    }
  }

  // Which detectors a frame is scored on: a detector runs only where its result counts (HOG
  // native takes about 2 s a frame, each cascade a few tenths).
  struct Needs {
    bool hog{false}, frontal{false}, profile{false};
  };

  static Needs needs_of(const std::vector<PersonLabel>& labels, const cv::Size& image) {
    Needs needs;
    needs.hog = needs.frontal = needs.profile = labels.empty();
    for (const PersonLabel& label : labels) {
      needs.hog =
          needs.hog || (fully_visible(label) && label.distance_m >= 2.0 && label.distance_m <= 6.0);
      if (near_unmasked_face(label, image)) {
        // Every such face is on the frontal cascades' curve of turns.
        needs.frontal = true;
        needs.profile = needs.profile || turned_face(label);
      }
    }
    needs.frontal = needs.frontal || every_face_turned(labels, kEveryFaceTurnedDeg);
    return needs;
  }

  // Frames whose frontal detections on people are all false.
  static bool every_face_turned(const std::vector<PersonLabel>& labels, double more_than_deg) {
    return !labels.empty() &&
           std::all_of(labels.begin(), labels.end(), [more_than_deg](const PersonLabel& label) {
             return label.face_yaw_deg > more_than_deg;
           });
  }

  FaceDetections detect_faces(const cv::Mat& grey, const Needs& needs) {
    FaceDetections found;
    if (needs.frontal) {
      found.alt2 = cascade_faces(alt2_, grey);
      found.frontal_default = cascade_faces(frontal_default_, grey);
    }
    if (needs.profile) {
      found.profile = profile_faces(profile_, grey);
    }
    return found;
  }

  // HOG's people are pedestrians: those seated are not counted.
  static bool fully_visible(const PersonLabel& label) {
    return label.occlusion < 0.01 && !label.truncated && !label.seated;
  }

  static bool near_unmasked(const PersonLabel& label) {
    return label.face_box && !label.mask && label.distance_m >= 0.8 && label.distance_m <= 3.0;
  }

  // A face cut by the image's border (the COCO export's `truncated` face) is not one a face
  // detector can find whole: it is not scored.
  static bool cut_by_border(const PersonLabel& label, const cv::Size& image) {
    return label.face_box && label.face_box->reaches_border(image.width, image.height);
  }

  static bool near_unmasked_face(const PersonLabel& label, const cv::Size& image) {
    return near_unmasked(label) && !cut_by_border(label, image);
  }

  // The faces the frontal cascades' recall counts and the profile cascade's.
  static bool frontal_face(const PersonLabel& label) {
    return label.face_yaw_deg <= kFrontalWithinDeg;
  }
  static bool turned_face(const PersonLabel& label) {
    return label.face_yaw_deg >= kTurnedPastFrontalDeg;
  }

  // The person box a HOG window is scored with.
  using PersonInWindow = rendering::PixelBox (*)(const cv::Rect&);

  // HOG's windows on `image` resized by `scale`, as person boxes in the image's pixels.
  std::vector<cv::Rect> hog_people(const cv::Mat& image, double scale, const cv::Size& stride,
                                   const cv::Size& padding, PersonInWindow person_in) {
    cv::Mat resized = image;
    if (scale != 1.0) {
      cv::resize(image, resized, cv::Size(), scale, scale, cv::INTER_AREA);
    }
    std::vector<cv::Rect> windows, people;
    hog_.detectMultiScale(resized, windows, 0.0, stride, padding, 1.05, 2.0);
    for (const cv::Rect& w : windows) {
      const rendering::PixelBox person =
          person_in(cv::Rect(cvRound(w.x / scale), cvRound(w.y / scale), cvRound(w.width / scale),
                             cvRound(w.height / scale)));
      people.emplace_back(person.x, person.y, person.width, person.height);
    }
    return people;
  }

  // HOG at native resolution as OpenCV's two people detection samples run it (window stride 8,
  // scale step 1.05): the C++ sample on the grey image without padding, scored with Dalal and
  // Triggs' person box; the Python sample on the colour image with 32 pixels of padding, which
  // lets a window reach past the image's border, scored with the box it draws. And at 0.35 of the
  // size, as test_detector_study runs it.
  void score_hog(const cv::Mat& rgb, const cv::Mat& grey, const std::vector<PersonLabel>& labels) {
    const std::vector<cv::Rect> native =
        hog_people(grey, 1.0, cv::Size(8, 8), cv::Size(), person_in_hog_window);
    const std::vector<cv::Rect> padded =
        hog_people(rgb, 1.0, cv::Size(8, 8), cv::Size(32, 32), person_drawn_in_hog_window);
    const std::vector<cv::Rect> scaled =
        hog_people(grey, kHogScale, cv::Size(4, 4), cv::Size(32, 32), person_in_hog_window);
    for (const PersonLabel& label : labels) {
      if (fully_visible(label) && label.distance_m >= 3.0 && label.distance_m <= 6.0) {
        hog_native_.add(label, any_overlaps(native, label.body_box));
        hog_padded_.add(label, any_overlaps(padded, label.body_box));
      }
      if (fully_visible(label) && label.distance_m >= 2.0 && label.distance_m <= 6.0) {
        hog_scaled_.add(label, any_overlaps(scaled, label.body_box));
      }
    }
    if (labels.empty()) {
      hog_native_empty_.add(static_cast<int>(native.size()));
      hog_padded_empty_.add(static_cast<int>(padded.size()));
      hog_scaled_empty_.add(static_cast<int>(scaled.size()));
    }
  }

  void score_faces(const FaceDetections& found, const std::vector<PersonLabel>& labels,
                   const cv::Size& image, int e) {
    for (const PersonLabel& label : labels) {
      if (e == 0) {
        count_cut_face(label, image);
      }
      if (!near_unmasked_face(label, image)) {
        continue;
      }
      alt2_by_turn_[e].add(label.face_yaw_deg, any_centred(found.alt2, *label.face_box));
      default_by_turn_[e].add(label.face_yaw_deg,
                              any_centred(found.frontal_default, *label.face_box));
      if (frontal_face(label)) {
        alt2_recall_[e].add(label, any_overlaps(found.alt2, *label.face_box));
        default_recall_[e].add(label, any_overlaps(found.frontal_default, *label.face_box));
      } else if (turned_face(label)) {
        profile_recall_[e].add(label, any_overlaps(found.profile, *label.face_box));
        profile_centred_[e].add(label, any_centred(found.profile, *label.face_box));
      }
    }
    if (every_face_turned(labels, kEveryFaceTurnedDeg)) {
      const int alt2_on_people = detections_on_people(found.alt2, labels);
      const int default_on_people = detections_on_people(found.frontal_default, labels);
      alt2_turned_[e].add(alt2_on_people);
      default_turned_[e].add(default_on_people);
      if (every_face_turned(labels, kTurnedPastFrontalDeg)) {
        alt2_profiles_only_[e].add(alt2_on_people);
        default_profiles_only_[e].add(default_on_people);
      }
      alt2_turned_faces_[e].add(detections_on_faces(found.alt2, labels));
      default_turned_faces_[e].add(detections_on_faces(found.frontal_default, labels));
      alt2_turned_away_[e].add(
          detections_on_people_turned(found.alt2, labels, kTurnedPastFrontalDeg));
      default_turned_away_[e].add(
          detections_on_people_turned(found.frontal_default, labels, kTurnedPastFrontalDeg));
    }
    if (labels.empty()) {
      alt2_empty_[e].add(static_cast<int>(found.alt2.size()));
      default_empty_[e].add(static_cast<int>(found.frontal_default.size()));
      profile_empty_[e].add(static_cast<int>(found.profile.size()));
    }
  }

  // A crop twice the face's size around each face the frontal recall counts and a cascade missed.
  void save_frontal_misses(const FaceDetections& found, const std::vector<PersonLabel>& labels,
                           const cv::Mat& rgb, const std::string& frame) const {
    for (const PersonLabel& label : labels) {
      if (!near_unmasked_face(label, rgb.size()) || !frontal_face(label)) {
        continue;
      }
      const rendering::PixelBox& face = *label.face_box;
      for (const auto& [name, detections] :
           {std::pair{"alt2", &found.alt2}, std::pair{"default", &found.frontal_default}}) {
        if (!any_overlaps(*detections, face)) {
          save_crop(rgb, face,
                    frame + "_person" + std::to_string(label.person_id) + "_tone" +
                        std::to_string(label.skin_tone) + "_" + name + ".png");
        }
      }
    }
  }

  // A crop twice the window's size around each frontal detection on someone when every face is
  // turned: what the turned-heads rate counts. `frame` names the preprocessing too.
  void save_turned_detections(const FaceDetections& found, const std::vector<PersonLabel>& labels,
                              const cv::Mat& rgb, const std::string& frame) const {
    if (!every_face_turned(labels, kEveryFaceTurnedDeg)) {
      return;
    }
    for (const auto& [name, detections] :
         {std::pair{"alt2", &found.alt2}, std::pair{"default", &found.frontal_default}}) {
      for (const cv::Rect& window : *detections) {
        const PersonLabel* under = person_under(window, labels);
        if (under != nullptr) {
          save_crop(rgb, box_of(window),
                    "false_" + frame + "_" + name + "_at_" + std::to_string(window.x) + "_" +
                        std::to_string(window.y) + "_yaw" +
                        std::to_string(static_cast<int>(under->face_yaw_deg)) + ".png");
        }
      }
    }
  }

  // The first person the window falls on, if any.
  static const PersonLabel* person_under(const cv::Rect& window,
                                         const std::vector<PersonLabel>& labels) {
    const auto under = std::find_if(labels.begin(), labels.end(), [&](const PersonLabel& label) {
      return on_person(window, label);
    });
    return under == labels.end() ? nullptr : &*under;
  }

  // A crop twice the size of `box` (a face or a detection window) around it.
  void save_crop(const cv::Mat& rgb, const rendering::PixelBox& box,
                 const std::string& name) const {
    const cv::Rect around =
        cv::Rect(box.x - box.width / 2, box.y - box.height / 2, 2 * box.width, 2 * box.height) &
        cv::Rect(0, 0, rgb.cols, rgb.rows);
    cv::Mat crop;
    cv::cvtColor(rgb(around), crop, cv::COLOR_RGB2BGR);
    const std::string file = misses_dir_ + "/" + name;
    if (!cv::imwrite(file, crop)) {
      std::fprintf(stderr, "detector_study: cannot write %s\n", file.c_str());
      std::exit(1);
    }
  }

  // Faces the recall would count but for the image's border cutting them.
  void count_cut_face(const PersonLabel& label, const cv::Size& image) {
    const bool cut = near_unmasked(label) && cut_by_border(label, image);
    cut_frontal_ += cut && frontal_face(label) ? 1 : 0;
    cut_turned_ += cut && turned_face(label) ? 1 : 0;
  }

  std::string misses_dir_;
  bool faces_only_;
  cv::HOGDescriptor hog_;
  cv::CascadeClassifier alt2_, frontal_default_, profile_;
  int cut_frontal_{0}, cut_turned_{0};
  int frames_{0};
  Recall hog_native_, hog_padded_, hog_scaled_;
  FalseRate hog_native_empty_, hog_padded_empty_, hog_scaled_empty_;
  cv::Ptr<cv::CLAHE> clahe_{cv::createCLAHE(2.0, cv::Size(8, 8))};
  // Indexed as kPreprocessingNames.
  std::array<Recall, kPreprocessings> alt2_recall_, default_recall_, profile_recall_,
      profile_centred_;
  std::array<TurnCurve, kPreprocessings> alt2_by_turn_, default_by_turn_;
  std::array<FalseRate, kPreprocessings> alt2_turned_, default_turned_, alt2_turned_faces_,
      default_turned_faces_, alt2_turned_away_, default_turned_away_, alt2_profiles_only_,
      default_profiles_only_, alt2_empty_, default_empty_, profile_empty_;
};

void print_recall(const char* detector, const char* who, const Recall& r) {
  std::printf("| %s | %s | %d of %d | %.1f %% |", detector, who, r.found, r.total,
              Recall::rate(r.found, r.total));
  for (int tone = 1; tone <= kSkinTones; ++tone) {
    if (r.tone_total[tone] > 0) {
      std::printf(" %.0f %% (%d) |", Recall::rate(r.tone_found[tone], r.tone_total[tone]),
                  r.tone_total[tone]);
    } else {
      std::printf(" - |");
    }
  }
  const double gap = Recall::rate(r.tone_found[1], r.tone_total[1]) -
                     Recall::rate(r.tone_found[kSkinTones], r.tone_total[kSkinTones]);
  std::printf(" %+.1f |\n", gap);
}

// "25 deg", or with `upper` "60-90 deg": the study's angles as its tables name them.
std::string degrees(double angle_deg, const char* upper = "") {
  return std::to_string(static_cast<int>(angle_deg)) + upper + " deg";
}

void print_turn_curve(const char* cascade, const TurnCurve& curve) {
  std::printf("| %s |", cascade);
  for (int bin = 0; bin < kTurnBins; ++bin) {
    std::printf(" %.0f %% (%d) |", Recall::rate(curve.found[bin], curve.total[bin]),
                curve.found[bin]);
  }
  std::printf("\n");
}

void print_false(const char* detector, const char* frames, const FalseRate& f) {
  std::printf("| %s | %s | %d in %d | %.3f |\n", detector, frames, f.detections, f.frames,
              f.frames > 0 ? double(f.detections) / f.frames : 0.0);
}

// Each frontal cascade's share of unmasked faces 0.8-3 m away with a window centred on them, by
// the face's turn: what it does between the faces its recall counts and those it should leave.
void Study::print_turn_curves() const {
  std::printf("\n| frontal cascade, window centred on the face |");
  for (int bin = 0; bin < kTurnBins; ++bin) {
    std::printf(" %.0f-%.0f deg |", kTurnBinsDeg[bin], kTurnBinsDeg[bin + 1]);
  }
  std::printf("\n|---|");
  for (int bin = 0; bin < kTurnBins; ++bin) {
    std::printf("---:|");
  }
  std::printf("\n| faces |");
  for (int bin = 0; bin < kTurnBins; ++bin) {
    std::printf(" %d |", alt2_by_turn_[0].total[bin]);
  }
  std::printf("\n");
  for (int e = 0; e < kPreprocessings; ++e) {
    const std::string p = kPreprocessingNames[e];
    print_turn_curve(("alt2" + p).c_str(), alt2_by_turn_[e]);
    print_turn_curve(("default" + p).c_str(), default_by_turn_[e]);
  }
}

void Study::print() const {
  std::printf(
      "\n%d frames; not scored, cut by the image's border: %d faces within %.0f deg, %d "
      "turned %.0f-90 deg\n\n",
      frames_, cut_frontal_, kFrontalWithinDeg, cut_turned_, kTurnedPastFrontalDeg);
  std::printf(
      "| detector | who | found | recall | tone 1 | tone 2 | tone 3 | tone 4 | tone 5 | tone 6 | "
      "tone 1 - tone 6 (points) |\n|---|---|---|---|---|---|---|---|---|---|---|\n");
  if (!faces_only_) {
    print_recall("HOG, native", "fully visible, 3-6 m", hog_native_);
    print_recall("HOG, native, Python sample", "fully visible, 3-6 m", hog_padded_);
    print_recall("HOG, 0.35 of the image", "fully visible, 2-6 m", hog_scaled_);
  }
  for (int e = 0; e < kPreprocessings; ++e) {
    const std::string p = kPreprocessingNames[e];
    const std::string frontal = "unmasked faces within " + degrees(kFrontalWithinDeg) + ", 0.8-3 m";
    const std::string turned =
        "unmasked faces turned " + degrees(kTurnedPastFrontalDeg, "-90") + ", 0.8-3 m";
    print_recall(("frontal alt2" + p).c_str(), frontal.c_str(), alt2_recall_[e]);
    print_recall(("frontal default" + p).c_str(), frontal.c_str(), default_recall_[e]);
    print_recall(("profile, IoU >= 0.5" + p).c_str(), turned.c_str(), profile_recall_[e]);
    print_recall(("profile, centred" + p).c_str(), turned.c_str(), profile_centred_[e]);
  }
  print_turn_curves();
  std::printf("\n| detector | frames | detections | per frame |\n|---|---|---|---|\n");
  if (!faces_only_) {
    print_false("HOG, native", "nobody in view", hog_native_empty_);
    print_false("HOG, native, Python sample", "nobody in view", hog_padded_empty_);
    print_false("HOG, 0.35 of the image", "nobody in view", hog_scaled_empty_);
  }
  const std::string every_face_turned =
      "every face turned > " + degrees(kEveryFaceTurnedDeg) + " (on people)";
  const std::string turned_away =
      "of them, on someone turned " + degrees(kTurnedPastFrontalDeg) + " or more";
  const std::string profiles_only =
      "every face turned > " + degrees(kTurnedPastFrontalDeg) + " (on people)";
  for (int e = 0; e < kPreprocessings; ++e) {
    const std::string p = kPreprocessingNames[e];
    print_false(("frontal alt2" + p).c_str(), every_face_turned.c_str(), alt2_turned_[e]);
    print_false(("frontal default" + p).c_str(), every_face_turned.c_str(), default_turned_[e]);
    print_false(("frontal alt2" + p).c_str(), "of them, boxes on a face (IoU >= 0.5)",
                alt2_turned_faces_[e]);
    print_false(("frontal default" + p).c_str(), "of them, boxes on a face (IoU >= 0.5)",
                default_turned_faces_[e]);
    print_false(("frontal alt2" + p).c_str(), turned_away.c_str(), alt2_turned_away_[e]);
    print_false(("frontal default" + p).c_str(), turned_away.c_str(), default_turned_away_[e]);
    print_false(("frontal alt2" + p).c_str(), profiles_only.c_str(), alt2_profiles_only_[e]);
    print_false(("frontal default" + p).c_str(), profiles_only.c_str(), default_profiles_only_[e]);
    print_false(("frontal alt2" + p).c_str(), "nobody in view", alt2_empty_[e]);
    print_false(("frontal default" + p).c_str(), "nobody in view", default_empty_[e]);
    print_false(("profile" + p).c_str(), "nobody in view", profile_empty_[e]);
  }
}

rendering::CameraRigConfig head_camera_every(double every_s) {
  rendering::CameraRigConfig config;
  for (rendering::CameraSpec& spec : config.cameras) {
    spec.enabled = spec.name == "head_front_camera";
    spec.rate_hz = 1.0 / every_s;
  }
  return config;
}

// Renders the scenario's episodes (seeds 1, 2, ...) into the study until it has `frames` of them.
void study_scenario(const std::string& name, const Options& options,
                    const engine::EpisodeConfig& config, Study& study) {
  const scenario::Scenario scenario = scenario::load_scenario_file(
      scenario::scenario_file_of(name, std::string(ARI_SOURCE_DIR) + "/scenarios"));
  rendering::CameraRig rig(head_camera_every(options.every_s));
  rig.set_world(scenario.scene.world, rendering::SceneStyle{});
  int frames = 0, empty = 0;
  uint64_t seed = 1;
  for (; frames < options.frames_per_scenario; ++seed) {
    engine::Episode episode(scenario, seed, config);
    rendering::SnapshotCameras cameras(rig, seed);
    for (int in_episode = 0; in_episode < options.frames_per_episode &&
                             frames < options.frames_per_scenario && !episode.finished();
         episode.step()) {
      for (const rendering::LabelledImage& image : cameras.render_due(episode.snapshot())) {
        char frame[64];
        std::snprintf(frame, sizeof(frame), "_%llu_%06.1fs", static_cast<unsigned long long>(seed),
                      image.time_s);
        study.add(image.colour, image.labels, name + frame);
        empty += image.labels.empty() ? 1 : 0;
        ++frames;
        ++in_episode;
      }
    }
  }
  std::fprintf(stderr, "detector_study: %s: %d frames (%d showing nobody) of seeds 1-%llu\n",
               name.c_str(), frames, empty, static_cast<unsigned long long>(seed - 1));
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const Options options = parse(argc, argv);
    const engine::EpisodeConfig config =
        engine::EpisodeConfig::load(std::string(ARI_SOURCE_DIR) + "/config");
    Study study(options.misses_dir, options.faces_only);
    for (const std::string& name : options.scenarios) {
      study_scenario(name, options, config, study);
    }
    study.print();
  } catch (const core::ConfigError& e) {
    usage(e.what());
  }
  return 0;
}
