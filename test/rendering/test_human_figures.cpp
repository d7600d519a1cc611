#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <set>
#include <string>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/rendering/image_labels.hpp"
#include "ari_social_sim/rendering/people_figures.hpp"
#include "ari_social_sim/rendering/renderer.hpp"
#include "render_test_scenes.hpp"

namespace ari_social_sim::rendering {
namespace {

constexpr double kDeg = M_PI / 180.0;

FigureInput standing_at(uint32_t id, const Eigen::Vector2d& position, double facing) {
  FigureInput input;
  input.traits.id = id;
  input.pose = {position, facing};
  input.face_yaw_rad = facing;
  return input;
}

TEST(HumanAppearance, TheSameTraitsAndSeedGiveTheSameLookAndStaturesFollowTheSurveys) {
  const HumanTraits traits{7, 40.0, model::Gender::kFemale, false};
  const HumanAppearance a = appearance_of(traits, 3), b = appearance_of(traits, 3);
  EXPECT_EQ(a.height_m, b.height_m);
  EXPECT_TRUE(a.skin == b.skin && a.top == b.top && a.hair == b.hair);
  EXPECT_NE(appearance_of(traits, 4).height_m, a.height_m);

  // Adults: mean and spread of stature per gender; six skin tones in about equal shares.
  for (const auto& [gender, mean] :
       {std::pair{model::Gender::kMale, 1.75}, std::pair{model::Gender::kFemale, 1.62}}) {
    double sum = 0.0, squares = 0.0;
    std::map<std::array<float, 3>, int> tones;
    std::map<int, std::set<float>> luma_by_label;  // the skin_tone label, for recall by tone
    constexpr int kPeople = 3000;
    for (uint32_t id = 0; id < kPeople; ++id) {
      const HumanAppearance look = appearance_of({id, 35.0, gender, false}, 11);
      sum += look.height_m;
      squares += look.height_m * look.height_m;
      ++tones[{look.skin.x(), look.skin.y(), look.skin.z()}];
      luma_by_label[look.skin_tone].insert(look.skin.dot(Eigen::Vector3f(0.299f, 0.587f, 0.114f)));
    }
    // Labels 1 to 6, one colour each, each darker than the one before.
    ASSERT_EQ(luma_by_label.size(), 6u);
    EXPECT_EQ(luma_by_label.begin()->first, 1);
    float lighter = 1.0f;
    for (const auto& [label, lumas] : luma_by_label) {
      ASSERT_EQ(lumas.size(), 1u) << label;
      EXPECT_LT(*lumas.begin(), lighter) << label;
      lighter = *lumas.begin();
    }
    const double average = sum / kPeople;
    const double spread = std::sqrt(squares / kPeople - average * average);
    std::printf("%s: mean %.3f m, sd %.3f m, %zu skin tones\n",
                gender == model::Gender::kMale ? "men" : "women", average, spread, tones.size());
    EXPECT_NEAR(average, mean, 0.01);
    EXPECT_NEAR(spread, 0.07, 0.01);
    ASSERT_EQ(tones.size(), 6u);
    for (const auto& [tone, count] : tones) {
      EXPECT_NEAR(double(count) / kPeople, 1.0 / 6.0, 0.03);
    }
  }
  // A six-year-old is about 1.13 m tall (Weech), with a head a larger share of it.
  const HumanAppearance child = appearance_of({1, 6.0, model::Gender::kMale, false}, 1);
  EXPECT_NEAR(child.height_m, 1.13, 0.1);
  EXPECT_GT(child.head_height_m / child.height_m, 0.16);
}

// Hair darkens with skin as it does in people: black hair for most of the darkest tone, blond and
// red hair mostly with the lightest; over all tones black the most common and red about 2 %.
TEST(HumanAppearance, HairDarkensWithSkinTone) {
  constexpr int kPeople = 12000;
  std::array<int, 7> people{}, black{}, blond{}, red{};
  for (uint32_t id = 0; id < kPeople; ++id) {
    // At 25 nobody is grey yet.
    const HumanAppearance look = appearance_of({id, 25.0, model::Gender::kFemale, false}, 2);
    const int tone = look.skin_tone;
    ++people[tone];
    black[tone] += look.hair.x() < 0.15f ? 1 : 0;
    blond[tone] += look.hair.y() > 0.5f ? 1 : 0;
    red[tone] += look.hair.x() - look.hair.y() > 0.2f ? 1 : 0;
  }
  const auto share = [&](const std::array<int, 7>& counts, int tone) {
    return static_cast<double>(counts[tone]) / people[tone];
  };
  EXPECT_NEAR(share(black, 6), 0.85, 0.03);
  EXPECT_NEAR(share(black, 1), 0.05, 0.02);
  EXPECT_NEAR(share(blond, 1), 0.22, 0.03);
  EXPECT_LT(share(blond, 6), 0.03);
  EXPECT_EQ(red[5] + red[6], 0);
  for (int tone = 2; tone <= 6; ++tone) {
    EXPECT_GT(share(black, tone), share(black, tone - 1)) << tone;
  }
  int all_black = 0, all_red = 0;
  for (int tone = 1; tone <= 6; ++tone) {
    all_black += black[tone];
    all_red += red[tone];
  }
  EXPECT_NEAR(static_cast<double>(all_black) / kPeople, 0.46, 0.02);
  EXPECT_NEAR(static_cast<double>(all_red) / kPeople, 0.023, 0.006);
}

// Eye colour goes with skin tone as hair does: brown for nearly everyone of the darker tones and a
// quarter of the lightest, blue-grey for over half of the lightest; over all tones brown about
// three quarters (70-79 % of the world's people).
TEST(HumanAppearance, EyesAreBrownForTheDarkerTones) {
  constexpr int kPeople = 12000;
  std::array<int, 7> people{}, brown{}, blue{};
  for (uint32_t id = 0; id < kPeople; ++id) {
    const HumanAppearance look = appearance_of({id, 30.0, model::Gender::kMale, false}, 5);
    ++people[look.skin_tone];
    // Brown irises are red over green and blue; blue-grey ones blue over red; green-hazel ones
    // green over red.
    const Eigen::Vector3f& iris = look.iris;
    brown[look.skin_tone] += iris.x() > iris.y() && iris.x() > iris.z() ? 1 : 0;
    blue[look.skin_tone] += iris.z() > iris.x() ? 1 : 0;
  }
  const auto share = [&](const std::array<int, 7>& counts, int tone) {
    return static_cast<double>(counts[tone]) / people[tone];
  };
  EXPECT_EQ(brown[6], people[6]);
  EXPECT_GT(share(brown, 5), 0.97);
  EXPECT_NEAR(share(brown, 1), 0.25, 0.03);
  EXPECT_NEAR(share(blue, 1), 0.55, 0.03);
  EXPECT_EQ(blue[5] + blue[6], 0);
  const int all_brown = std::accumulate(brown.begin(), brown.end(), 0);
  EXPECT_NEAR(static_cast<double>(all_brown) / kPeople, 0.735, 0.02);
}

// Grey hairs come with middle age, later and fewer with darker skin, as Panhard et al. (2012)
// counted in 4,192 people: at 50, 6-23 % had half their hair grey; between 45 and 65, 74 % had
// grey hairs, 27 % of their hair on average.
TEST(HumanAppearance, HairGreysFromMiddleAgeLaterWithDarkerSkin) {
  constexpr int kPeople = 12000;
  const auto look_at = [](uint32_t id, double age) {
    return appearance_of({id, age, model::Gender::kMale, false}, 3);
  };
  std::array<int, 7> people{}, half_grey_at_50{};
  double share_25 = 0.0, share_45_to_65 = 0.0;
  int greying_45_to_65 = 0, lighter_at_85 = 0;
  for (uint32_t id = 0; id < kPeople; ++id) {
    const HumanAppearance at_50 = look_at(id, 50.0);
    ++people[at_50.skin_tone];
    half_grey_at_50[at_50.skin_tone] += at_50.hair_grey_share >= 0.5 ? 1 : 0;
    share_25 += look_at(id, 25.0).hair_grey_share;
    const HumanAppearance middle_aged = look_at(id, 45.0 + (id % 21));
    share_45_to_65 += middle_aged.hair_grey_share;
    greying_45_to_65 += middle_aged.hair_grey_share > 0.0 ? 1 : 0;
    const auto luma = [](const HumanAppearance& look) { return look.hair.sum(); };
    lighter_at_85 += luma(look_at(id, 85.0)) > luma(look_at(id, 30.0)) ? 1 : 0;
  }
  const auto share_of = [&](int tone) {
    return static_cast<double>(half_grey_at_50[tone]) / people[tone];
  };
  std::printf(
      "half grey at 50: tone 1 %.3f, tone 6 %.3f; 45-65: %.3f greying, mean share %.3f; "
      "mean share at 25 %.4f\n",
      share_of(1), share_of(6), static_cast<double>(greying_45_to_65) / kPeople,
      share_45_to_65 / kPeople, share_25 / kPeople);
  // The lightest and darkest tones stand for the survey's groups that grey first and last.
  EXPECT_NEAR(share_of(1), 0.13, 0.03);
  EXPECT_NEAR(share_of(6), 0.055, 0.02);
  EXPECT_NEAR(static_cast<double>(greying_45_to_65) / kPeople, 0.74, 0.06);
  EXPECT_NEAR(share_45_to_65 / kPeople, 0.27, 0.04);
  EXPECT_LT(share_25 / kPeople, 0.01);
  EXPECT_GT(lighter_at_85, 0.95 * kPeople);
}

// The hairline recedes from 25 to 65, men's to 0.04 of the head's height and women's to 0.02;
// nobody's look draws anything for it, so the rest of a look does not change with age.
TEST(HumanAppearance, TheHairlineRecedesWithAgeFurtherForMen) {
  const auto look_at = [](double age, model::Gender gender) {
    return appearance_of({7, age, gender, false}, 11);
  };
  for (const model::Gender gender : {model::Gender::kMale, model::Gender::kFemale}) {
    const double most = gender == model::Gender::kMale ? 0.04 : 0.02;
    EXPECT_DOUBLE_EQ(look_at(20.0, gender).hairline_recession, 0.0);
    EXPECT_DOUBLE_EQ(look_at(25.0, gender).hairline_recession, 0.0);
    EXPECT_NEAR(look_at(45.0, gender).hairline_recession, 0.5 * most, 1e-12);
    EXPECT_NEAR(look_at(65.0, gender).hairline_recession, most, 1e-12);
    EXPECT_NEAR(look_at(90.0, gender).hairline_recession, most, 1e-12);
    EXPECT_EQ(look_at(70.0, gender).skin, look_at(30.0, gender).skin);
    EXPECT_EQ(look_at(70.0, gender).top, look_at(30.0, gender).top);
  }
}

// A person seen from the side 10 m away covers the image rows of their stature, plus at most 3 %
// (hair, and the perspective of their near side).
TEST(HumanFigure, RenderedFigureIsAsTallAsTheStatureAndStridesWhenWalking) {
  Renderer renderer;
  renderer.set_static_primitives({});
  const PinholeModel model = PinholeModel::from_horizontal_fov(1280, 960, 62.2 * kDeg);
  const Eigen::Isometry3d X_world_optical = test::level_camera_facing_x({0.0, 0.0, 1.0});
  constexpr double kDistance = 10.0;
  ViewOptions options;
  options.labels = true;
  RenderedImage image;
  double standing_width_px = 0.0;
  for (const double speed : {0.0, 1.3}) {
    FigureInput person = standing_at(5, {kDistance, 0.0}, M_PI / 2);  // across the view
    person.velocity_mps = {0.0, speed};
    PeopleFigures figures;
    figures.update(0.0, {person});
    person.walked_m = 0.4 * speed;  // a quarter stride on: legs apart
    figures.update(0.4, {person});
    renderer.set_dynamic_mesh(figures.mesh());
    renderer.render(model, X_world_optical, options, image);
    const cv::Rect box = cv::boundingRect(image.labels > 0);
    const double height_m = box.height * kDistance / model.fy;
    const double stature = figures.posed()[0].figure->appearance().height_m;
    std::printf("speed %.1f: %d x %d px, %.3f m tall for a stature of %.3f m\n", speed, box.width,
                box.height, height_m, stature);
    if (speed == 0.0) {
      EXPECT_GE(height_m, stature - kDistance / model.fy);
      EXPECT_LE(height_m, 1.03 * stature);
      standing_width_px = box.width;
    } else {
      // The stride opens the legs: the side view is at least 0.3 m wider than standing.
      EXPECT_GT((box.width - standing_width_px) * kDistance / model.fx, 0.3);
    }
  }
}

// A head close up, 0.7 m in front of a level camera at its height, turned 0, 45, 90 and 180
// degrees away from the camera. The head hides what faces away: turned, the far eye is hidden and
// in profile the nose's tip is the face's outline; from behind no eye shows. The four views are
// written side by side to head_views_ID.png in the test's temporary folder, to look at.
TEST(HumanFigure, TheHeadHidesWhatFacesAwayFromTheCamera) {
  Renderer renderer;
  renderer.set_static_primitives({});
  const PinholeModel model = PinholeModel::from_horizontal_fov(320, 320, 30.0 * kDeg);
  ViewOptions options;
  options.labels = true;
  options.depth = true;
  RenderedImage image;
  for (const uint32_t id : {3u, 4u}) {
    std::vector<cv::Mat> views;
    for (const double turn_deg : {0.0, 45.0, 90.0, 180.0}) {
      PeopleFigures figures;
      figures.update(0.0, {standing_at(id, {0.7, 0.0}, M_PI + turn_deg * kDeg)});
      PosedPerson person = figures.posed()[0];
      // The weight on both legs: the head straight above the feet, 0.7 m from the camera.
      person.pose.weight_side = 0.0;
      RenderMesh mesh;
      person.figure->append_posed(person.pose, person.body_label, person.face_label, mesh);
      const Eigen::Isometry3d X_world_head = person.figure->head_frame(person.pose);
      const Eigen::Isometry3d X_world_optical =
          test::level_camera_facing_x({0.0, 0.0, X_world_head.translation().z()});
      if (turn_deg == 0.0) {
        std::printf("person %u: %zu triangles\n", id, mesh.vertex_count() / 3);
      }
      renderer.set_dynamic_mesh(mesh);
      renderer.render(model, X_world_optical, options, image);
      const Eigen::Isometry3d X_optical_head = X_world_optical.inverse() * X_world_head;
      int eyes_seen = 0;
      for (const Eigen::Vector3d& eye : person.figure->eyes()) {
        const Eigen::Vector3d at = X_optical_head * eye;
        const Eigen::Vector2d pixel = *model.project(at);
        const float depth = image.depth.at<float>(cvRound(pixel.y()), cvRound(pixel.x()));
        eyes_seen += std::abs(depth - at.z()) < 0.004 ? 1 : 0;
      }
      // At 45 degrees the nose hides the far iris's centre.
      const int most = turn_deg < 10.0 ? 2 : (turn_deg < 120.0 ? 1 : 0);
      EXPECT_LE(eyes_seen, most) << "person " << id << " turned " << turn_deg << " deg";
      EXPECT_GE(eyes_seen, turn_deg < 60.0 ? most : 0);
      if (turn_deg == 90.0) {
        // Turned to the image's right: nothing of the face lies right of the nose's tip.
        const Eigen::Vector2d tip =
            *model.project(X_optical_head * person.figure->face_outline().back());
        const cv::Mat face = image.labels == person.face_label;
        const cv::Rect box = cv::boundingRect(face);
        std::printf("person %u in profile: nose tip at u %.1f, the face reaches u %d\n", id,
                    tip.x(), box.x + box.width - 1);
        EXPECT_NEAR(box.x + box.width - 1, tip.x(), 3.0);
      }
      cv::Mat bgr;
      cv::cvtColor(image.colour, bgr, cv::COLOR_RGB2BGR);
      views.push_back(bgr);
    }
    cv::Mat strip;
    cv::hconcat(views, strip);
    const std::string path = ::testing::TempDir() + "head_views_" + std::to_string(id) + ".png";
    cv::imwrite(path, strip);
    std::printf("wrote %s\n", path.c_str());
  }
}

// A face close up and level, with each emotion of the world: anger and distress tilt the brows and
// joy lifts them (pixels above the eyes change), joy and distress turn the mouth's corners (pixels
// below the nose's tip change); the world's emotion reaches the figure.
TEST(HumanFigure, ExpressionsMoveTheBrowsAndTheMouthsCorners) {
  Renderer renderer;
  renderer.set_static_primitives({});
  const PinholeModel model = PinholeModel::from_horizontal_fov(320, 320, 30.0 * kDeg);
  auto face_of = [&](model::Emotion emotion, const PosedPerson** posed, PeopleFigures& figures) {
    world::HumanSnapshot human;
    human.id = 4;
    human.pose = {{0.7, 0.0}, M_PI};
    human.gaze.direction_rad = M_PI;
    human.emotion = emotion;
    figures.update(0.0, {figure_input_of(human)});
    *posed = &figures.posed()[0];
    const Eigen::Isometry3d X_world_optical = test::level_camera_facing_x(
        {0.0, 0.0, (*posed)->figure->head_frame((*posed)->pose).translation().z()});
    renderer.set_dynamic_mesh(figures.mesh());
    RenderedImage image;
    renderer.render(model, X_world_optical, ViewOptions{}, image);
    cv::Mat grey;
    cv::cvtColor(image.colour, grey, cv::COLOR_RGB2GRAY);
    return std::pair{grey, X_world_optical};
  };
  PeopleFigures neutral_figures;
  const PosedPerson* neutral = nullptr;
  const auto [neutral_face, X_world_optical] =
      face_of(model::Emotion::kNeutral, &neutral, neutral_figures);
  const Eigen::Isometry3d X_optical_head =
      X_world_optical.inverse() * neutral->figure->head_frame(neutral->pose);
  const double eyes_v = model.project(X_optical_head * neutral->figure->eyes()[0])->y();
  const double nose_v = model.project(X_optical_head * neutral->figure->face_outline().back())->y();
  for (const model::Emotion emotion :
       {model::Emotion::kHappy, model::Emotion::kAngry, model::Emotion::kDisturbed}) {
    PeopleFigures figures;
    const PosedPerson* posed = nullptr;
    const cv::Mat face = face_of(emotion, &posed, figures).first;
    EXPECT_EQ(posed->figure->appearance().emotion, emotion);
    const cv::Mat changed = cv::abs(face - neutral_face) + cv::abs(neutral_face - face) > 20;
    const int brows = cv::countNonZero(changed.rowRange(0, cvRound(eyes_v)));
    const int mouth = cv::countNonZero(changed.rowRange(cvRound(nose_v), changed.rows));
    std::printf("%s: %d pixels changed above the eyes, %d below the nose\n",
                model::to_string(emotion), brows, mouth);
    EXPECT_GE(brows, 40) << model::to_string(emotion);
    EXPECT_EQ(mouth >= 10, emotion != model::Emotion::kAngry) << model::to_string(emotion);
  }
}

TEST(PeopleFigures, HeadTurnsToTheGazeNodsAndTheMouthMovesOnlyWhileSpeaking) {
  FigureInput person = standing_at(2, {0.0, 0.0}, 0.0);
  PeopleFigures figures;
  for (const double gaze : {0.5, -0.9, 2.0}) {
    person.face_yaw_rad = gaze;
    figures.update(0.0, {person});
    const PosedPerson& posed = figures.posed()[0];
    const Eigen::Matrix3d R = posed.figure->head_frame(posed.pose).linear();
    const double head_yaw = std::atan2(R(1, 0), R(0, 0));
    EXPECT_NEAR(head_yaw,
                std::clamp(gaze, -HumanFigure::kMaxHeadTurnRad, HumanFigure::kMaxHeadTurnRad),
                1e-6);
  }
  // A nod tips the head forward: its x axis (out of the face) points down by the pitch.
  person.face_yaw_rad = 0.0;
  person.head_pitch_rad = 0.2;
  figures.update(0.0, {person});
  const PosedPerson& nodding = figures.posed()[0];
  const Eigen::Vector3d out_of_face =
      nodding.figure->head_frame(nodding.pose).linear() * Eigen::Vector3d::UnitX();
  EXPECT_NEAR(out_of_face.z(), -std::sin(0.2), 1e-6);
  person.head_pitch_rad = 0.0;
  double lowest = 1.0, highest = 0.0;
  for (const bool speaking : {false, true}) {
    person.speaking = speaking;
    for (double t = 0.0; t < 1.0; t += 0.01) {
      figures.update(t, {person});
      const double open = figures.posed()[0].pose.mouth_open;
      if (!speaking) {
        EXPECT_EQ(open, 0.0);
      } else {
        lowest = std::min(lowest, open);
        highest = std::max(highest, open);
      }
    }
  }
  EXPECT_LT(lowest, 0.05);
  EXPECT_GT(highest, 0.95);
}

TEST(PeopleFigures, FiguresAreBuiltOncePerPersonAndTheSameInputsGiveTheSameMesh) {
  std::vector<FigureInput> people{standing_at(1, {1.0, 0.0}, 0.0), standing_at(2, {2.0, 1.0}, 1.0)};
  people[1].velocity_mps = {0.8, 0.3};
  PeopleFigures a(5), b(5);
  for (double t = 0.0; t < 1.0; t += 0.1) {
    a.update(t, people);
    b.update(t, people);
  }
  EXPECT_EQ(a.mesh().vertices, b.mesh().vertices);
  const HumanFigure* first = a.posed()[0].figure;
  a.update(1.1, people);
  EXPECT_EQ(a.posed()[0].figure, first);  // kept, not rebuilt
  people[0].traits.mask = true;
  a.update(1.2, people);
  EXPECT_TRUE(a.posed()[0].figure->appearance().mask);  // rebuilt when the traits change
  a.update(1.3, {people[1]});
  ASSERT_EQ(a.posed().size(), 1u);
  EXPECT_EQ(a.posed()[0].id, 2u);
  EXPECT_EQ(a.owner_of(a.posed()[0].face_label)->face, true);
  EXPECT_FALSE(a.owner_of(5).has_value());
}

PinholeModel head_camera() {
  return PinholeModel::from_horizontal_fov(1280, 960, 62.2 * kDeg);
}

// `people` posed by `figures` and seen by the head camera from `camera_z` above the origin,
// looking along +x: the image with depth and labels, and the people's labels.
std::vector<PersonLabel> render_labelled(const std::vector<FigureInput>& people, double camera_z,
                                         PeopleFigures& figures, RenderedImage& image) {
  Renderer renderer;
  renderer.set_static_primitives({});
  const Eigen::Isometry3d X_world_optical = test::level_camera_facing_x({0.0, 0.0, camera_z});
  figures.update(0.0, people);
  renderer.set_dynamic_mesh(figures.mesh());
  ViewOptions options;
  options.labels = true;
  options.depth = true;
  renderer.render(head_camera(), X_world_optical, options, image);
  return label_people(renderer, head_camera(), X_world_optical, figures, image.labels);
}

// One person 4 m away hides part of another 6 m away on the same line of sight: the labels give
// the front one no occlusion and a face box, the back one an occlusion between 0.3 and 0.9 and,
// turned away, no face box; depth at the front person's pixels is their distance.
TEST(ImageLabels, OcclusionFaceBoxesAndDepthAgreeWithTheScene) {
  PeopleFigures figures;
  RenderedImage image;
  const std::vector<PersonLabel> labels = render_labelled(
      {standing_at(1, {4.0, 0.15}, M_PI), standing_at(2, {6.0, 0.0}, 0.0)}, 1.5, figures, image);
  ASSERT_EQ(labels.size(), 2u);
  const PersonLabel& front = labels[0].person_id == 1 ? labels[0] : labels[1];
  const PersonLabel& back = labels[0].person_id == 1 ? labels[1] : labels[0];
  std::printf("front: occlusion %.2f, face yaw %.1f deg; back: occlusion %.2f, face yaw %.1f\n",
              front.occlusion, front.face_yaw_deg, back.occlusion, back.face_yaw_deg);
  EXPECT_EQ(front.occlusion, 0.0);
  EXPECT_FALSE(front.truncated);
  EXPECT_FALSE(front.seated);
  EXPECT_NEAR(front.distance_m, 4.0, 0.01);
  ASSERT_TRUE(front.face_box.has_value());
  EXPECT_LT(front.face_yaw_deg, 10.0);
  EXPECT_GT(back.occlusion, 0.3);
  EXPECT_LT(back.occlusion, 0.9);
  EXPECT_FALSE(back.face_box.has_value());
  // The face box holds the face's labelled pixels, but for a bald crown above the hairline.
  const cv::Rect face(front.face_box->x, front.face_box->y, front.face_box->width,
                      front.face_box->height);
  const cv::Mat face_pixels = image.labels == figures.posed()[0].face_label;
  EXPECT_GE(cv::countNonZero(face_pixels(face)), 0.85 * cv::countNonZero(face_pixels));
  // Depth is consistent with the geometry: the front person's pixels lie within 0.4 m of 4 m (a
  // foot forward in the stance, the back of the head behind).
  double nearest = 1e9, farthest = 0.0;
  for (int v = 0; v < image.depth.rows; ++v) {
    for (int u = 0; u < image.depth.cols; ++u) {
      if (image.labels.at<uint16_t>(v, u) == figures.posed()[0].body_label) {
        nearest = std::min(nearest, double(image.depth.at<float>(v, u)));
        farthest = std::max(farthest, double(image.depth.at<float>(v, u)));
      }
    }
  }
  std::printf("front person's depth %.3f to %.3f m\n", nearest, farthest);
  EXPECT_GT(nearest, 3.6);
  EXPECT_LT(farthest, 4.4);
}

// The lowest labelled point (m above the floor) of a figure seen from its side, between
// `from_m` and `to_m` ahead of it: a level camera 3 m away at `camera_z` looks along +x at a
// figure at (3, 0) facing +y, so the figure's "ahead" is the image's left. At the height the
// point is expected at, the camera sees it on its middle row whatever its depth.
double lowest_point_m(const FigurePose& pose, const HumanFigure& figure, double from_m, double to_m,
                      double camera_z) {
  Renderer renderer;
  renderer.set_static_primitives({});
  RenderMesh mesh;
  figure.append_posed(pose, 1.0f, 2.0f, mesh);
  renderer.set_dynamic_mesh(mesh);
  const PinholeModel model = PinholeModel::from_horizontal_fov(1280, 960, 62.2 * kDeg);
  ViewOptions options;
  options.labels = true;
  RenderedImage image;
  renderer.render(model, test::level_camera_facing_x({0.0, 0.0, camera_z}), options, image);
  int lowest_row = -1;
  for (int u = static_cast<int>(model.cx - to_m * model.fx / 3.0);
       u <= static_cast<int>(model.cx - from_m * model.fx / 3.0); ++u) {
    for (int v = 0; v < image.labels.rows; ++v) {
      if (image.labels.at<uint16_t>(v, u) > 0) {
        lowest_row = std::max(lowest_row, v);
      }
    }
  }
  return camera_z - (lowest_row - model.cy) * 3.0 / model.fy;
}

TEST(HumanFigure, ASeatedFigureRestsOnTheSeatWithItsFeetOnTheFloorAndItsEyesAtSittingHeight) {
  for (const auto gender : {model::Gender::kFemale, model::Gender::kMale}) {
    const HumanFigure figure(appearance_of({3, 40.0, gender, false}, 5));
    FigurePose pose;
    pose.body = {{3.0, 0.0}, M_PI / 2};
    pose.seated = 1.0;
    // Thighs on the seat (0.45 m) up to its front edge 0.2 m ahead; soles on the floor ahead.
    const double thighs_z = lowest_point_m(pose, figure, 0.1, 0.2, kChairSeatHeightM);
    const double soles_z = lowest_point_m(pose, figure, 0.35, 0.6, 0.0);
    const Eigen::Vector3d eye = figure.head_frame(pose) * figure.eyes()[0];
    std::printf("%s, %.3f m tall, seated: thighs' underside %.3f m, soles %.3f m, eyes %.3f m\n",
                gender == model::Gender::kMale ? "man" : "woman", figure.appearance().height_m,
                thighs_z, soles_z, eye.z());
    EXPECT_NEAR(thighs_z, kChairSeatHeightM, 0.03);
    EXPECT_NEAR(soles_z, 0.0, 0.01);
    // Sitting eye height 0.74 m (women) to 0.79 m (men) above the seat (Pheasant and Haslegrave
    // 2006, British adults' medians; docs/references.md), so 1.19 to 1.24 m above the floor;
    // within 5 cm for a figure of about average stature.
    EXPECT_NEAR(eye.z(), gender == model::Gender::kMale ? 1.24 : 1.19, 0.05);
  }
}

TEST(PeopleFigures, SpeakersGestureWithTheirDominantHandInBeatsAndStopWhenSilent) {
  FigureInput person = standing_at(2, {0.0, 0.0}, 0.0);
  PeopleFigures figures;
  const auto dominant_hand_z = [&figures] {
    const PosedPerson& posed = figures.posed()[0];
    return posed.figure->hand_centre(posed.pose, posed.figure->appearance().left_handed).z();
  };
  figures.update(0.0, {person});
  const double at_rest = dominant_hand_z();
  // Speaking: the gesture rises within a second (time constant 0.35 s) and beats.
  person.speaking = true;
  double lowest = 10.0, highest = 0.0;
  for (double t = 0.02; t <= 3.0; t += 0.02) {
    figures.update(t, {person});
    if (t >= 1.5) {
      lowest = std::min(lowest, dominant_hand_z());
      highest = std::max(highest, dominant_hand_z());
    }
  }
  const double gesture = figures.posed()[0].pose.gesture;
  // Silent again: the arms fall back to rest.
  person.speaking = false;
  for (double t = 3.02; t <= 5.0; t += 0.02) {
    figures.update(t, {person});
  }
  std::printf(
      "dominant hand at rest %.3f m, gesturing %.3f to %.3f m, gesture %.3f, after %.3f m\n",
      at_rest, lowest, highest, gesture, dominant_hand_z());
  EXPECT_GT(gesture, 0.98);
  EXPECT_GT(lowest, at_rest + 0.15);  // the forearm up in front of the trunk
  EXPECT_GT(highest - lowest, 0.03);  // beats
  EXPECT_NEAR(dominant_hand_z(), at_rest, 0.01);
  EXPECT_LT(figures.posed()[0].pose.gesture, 0.01);
}

TEST(HumanFigure, TheOtherHandGesturesLessAndOneInTenIsLeftHanded) {
  int left_handed = 0;
  for (uint32_t id = 0; id < 2000; ++id) {
    left_handed += appearance_of({id, 35.0, model::Gender::kMale, false}, 4).left_handed ? 1 : 0;
  }
  EXPECT_NEAR(left_handed / 2000.0, 0.106, 0.02);
  const HumanFigure figure(appearance_of({5, 35.0, model::Gender::kFemale, false}, 1));
  FigurePose rest, gesturing;
  gesturing.gesture = 1.0;
  const bool left = figure.appearance().left_handed;
  const double dominant_rise =
      figure.hand_centre(gesturing, left).z() - figure.hand_centre(rest, left).z();
  const double other_rise =
      figure.hand_centre(gesturing, !left).z() - figure.hand_centre(rest, !left).z();
  EXPECT_GT(dominant_rise, 0.15);
  EXPECT_GT(other_rise, 0.3 * dominant_rise);
  EXPECT_LT(other_rise, 0.8 * dominant_rise);
}

TEST(HumanFigure, StandingUpTheTrunkLeansForwardThenTheHipsRise) {
  const HumanFigure figure(appearance_of({3, 70.0, model::Gender::kFemale, false}, 5));
  double previous_head_z = 0.0;
  for (const double seated : {1.0, 0.8, 0.5, 0.2, 0.0}) {
    FigurePose pose;
    pose.seated = seated;
    const Eigen::Vector3d head = figure.head_frame(pose).translation();
    std::printf("seated %.1f: head at x %.3f, z %.3f m\n", seated, head.x(), head.z());
    if (seated == 0.5) {
      EXPECT_GT(head.x(), 0.25);  // the head well ahead of the hips: the trunk leans forward
    }
    EXPECT_GE(head.z(), previous_head_z - 0.05);  // the head hardly drops, then rises
    previous_head_z = head.z();
  }
  FigurePose standing;
  EXPECT_NEAR(previous_head_z, figure.head_frame(standing).translation().z(), 1e-6);
}

// The vertices of a figure's mesh as points (RenderMesh: position first).
std::vector<Eigen::Vector3f> points_of(const RenderMesh& mesh) {
  std::vector<Eigen::Vector3f> points;
  for (size_t v = 0; v < mesh.vertex_count(); ++v) {
    const float* at = &mesh.vertices[v * RenderMesh::kFloatsPerVertex];
    points.emplace_back(at[0], at[1], at[2]);
  }
  return points;
}

std::vector<Eigen::Vector3f> posed_points(const HumanFigure& figure, const FigurePose& pose) {
  RenderMesh mesh;
  figure.append_posed(pose, 1.0f, 2.0f, mesh);
  return points_of(mesh);
}

TEST(HumanFigure, StandingOnTheLeftLegThePelvisMovesOverItTheRightKneeBendsTheFeetStay) {
  const HumanFigure figure(appearance_of({3, 40.0, model::Gender::kMale, false}, 5));
  FigurePose even;  // at the origin, facing +x: the figure's left is +y
  FigurePose on_left = even;
  on_left.weight_side = 1.0;
  const std::vector<Eigen::Vector3f> before = posed_points(figure, even);
  const std::vector<Eigen::Vector3f> after = posed_points(figure, on_left);
  ASSERT_EQ(before.size(), after.size());
  float feet_moved = 0.0f, right_knee_ahead = -1.0f, left_knee_ahead = -1.0f;
  float right_knee_before = -1.0f, left_knee_before = -1.0f;
  Eigen::Vector3f upper_body_moved = Eigen::Vector3f::Zero();
  int upper_body = 0;
  for (size_t v = 0; v < before.size(); ++v) {
    if (before[v].z() < 0.025f) {  // the feet: the shins end a little above
      feet_moved = std::max(feet_moved, (after[v] - before[v]).norm());
    } else if (before[v].z() > 1.2f) {
      upper_body_moved += after[v] - before[v];
      ++upper_body;
    } else if (before[v].z() > 0.4f && before[v].z() < 0.6f) {  // about the knees
      float& ahead_after = before[v].y() < 0.0f ? right_knee_ahead : left_knee_ahead;
      float& ahead_before = before[v].y() < 0.0f ? right_knee_before : left_knee_before;
      ahead_after = std::max(ahead_after, after[v].x());
      ahead_before = std::max(ahead_before, before[v].x());
    }
  }
  upper_body_moved /= static_cast<float>(upper_body);
  std::printf(
      "[ measured ] on the left leg: feet moved %.4f m at most, shoulders and head by "
      "(%.3f, %.3f, %.3f) m, the right knee %.3f m further forward, the left %.3f m\n",
      feet_moved, upper_body_moved.x(), upper_body_moved.y(), upper_body_moved.z(),
      right_knee_ahead - right_knee_before, left_knee_ahead - left_knee_before);
  EXPECT_LT(feet_moved, 0.002f);
  EXPECT_NEAR(upper_body_moved.y(), 0.03f, 0.002f);  // over the left leg
  EXPECT_NEAR(upper_body_moved.x(), 0.0f, 0.002f);
  EXPECT_NEAR(upper_body_moved.z(), 0.0f, 0.002f);
  EXPECT_GT(right_knee_ahead - right_knee_before, 0.02f);          // the free knee bends forward
  EXPECT_LT(std::abs(left_knee_ahead - left_knee_before), 0.01f);  // the loaded leg stays straight

  // The mirror image on the right leg, and nothing of it while walking or seated.
  FigurePose on_right = even;
  on_right.weight_side = -1.0;
  EXPECT_NEAR(figure.head_frame(on_right).translation().y(),
              figure.head_frame(even).translation().y() - 0.03, 1e-4);
  for (const auto& [amplitude, seated] : {std::pair{1.0, 0.0}, std::pair{0.0, 1.0}}) {
    FigurePose still = even, shifted = even;
    still.gait_amplitude = shifted.gait_amplitude = amplitude;
    still.seated = shifted.seated = seated;
    shifted.weight_side = 1.0;
    EXPECT_EQ(posed_points(figure, still), posed_points(figure, shifted))
        << "walking " << amplitude << ", seated " << seated;
  }
}

TEST(ImageLabels, ASeatedPersonsBodyAndFaceBoxesAreFound) {
  // ARI's head camera height, 2.5 m from a seated person facing it.
  FigureInput person = standing_at(1, {2.5, 0.0}, M_PI);
  person.seated = 1.0;
  PeopleFigures figures;
  RenderedImage image;
  const std::vector<PersonLabel> labels = render_labelled({person}, 1.4, figures, image);
  const PinholeModel model = head_camera();
  ASSERT_EQ(labels.size(), 1u);
  ASSERT_TRUE(labels[0].face_box.has_value());
  EXPECT_TRUE(labels[0].seated);
  const cv::Rect face(labels[0].face_box->x, labels[0].face_box->y, labels[0].face_box->width,
                      labels[0].face_box->height);
  const cv::Mat face_pixels = image.labels == figures.posed()[0].face_label;
  EXPECT_GE(cv::countNonZero(face_pixels(face)), 0.85 * cv::countNonZero(face_pixels));
  // The body box spans the seated figure: from the crown (about 1.3 m) to the soles, 1.4 m
  // below the camera at 2.5 m: rows cy + fy * (1.4 - z) / depth.
  const cv::Rect body = cv::boundingRect(image.labels > 0);
  const double top_z = 1.4 - (body.y - model.cy) * 2.5 / model.fy;
  std::printf("seated body box %d x %d px, top at %.3f m\n", body.width, body.height, top_z);
  EXPECT_NEAR(top_z, 1.3, 0.1);
  EXPECT_GT(face.y, body.y - 1);
}

}  // namespace
}  // namespace ari_social_sim::rendering
