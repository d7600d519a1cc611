#include <gtest/gtest.h>

#include "ari_social_sim/perception/person_registry.hpp"
#include "perception_scenes.hpp"

namespace ari_social_sim::perception {
namespace {

using test::human_at;

PerceivedBody body_of(model::ObjectId human, const std::string& id, double x, double y) {
  PerceivedBody body;
  body.human = human;
  body.body_id = id;
  body.person_id = person_id_of(human);
  body.X_map_body = {{x, y}, 0.0};
  return body;
}

TEST(PersonRegistry, PermanentIdsLinkedToTheirFeatures) {
  PersonRegistry registry({}, {}, core::Rng(1));
  world::WorldSnapshot snapshot = test::snapshot_with_ari(1.0);
  snapshot.humans = {human_at(10, 2.0, 0.0, 0.0), human_at(11, 3.0, 1.0, 0.0),
                     human_at(12, 4.0, 1.0, 0.0)};
  PerceivedFace face;
  face.human = 11;
  face.face_id = "faces";
  face.X_map_face = {{3.01, 1.0}, 0.0};
  PerceivedVoice voice;
  voice.human = 11;
  voice.voice_id = "voice";
  std::vector<PersonReport> reports;
  registry.update(snapshot, nullptr,
                  {body_of(10, "bodya", 2.0, 0.0), body_of(11, "bodyb", 3.0, 1.0)}, {face}, {voice},
                  reports);
  ASSERT_EQ(reports.size(), 2u);  // human 12 was never seen: not known
  EXPECT_EQ(reports[0].person_id, "human10");
  EXPECT_EQ(reports[0].name, "human 10");
  EXPECT_EQ(reports[0].body_id, "bodya");
  EXPECT_EQ(reports[0].face_id, "");
  EXPECT_TRUE(reports[0].tracked);
  EXPECT_DOUBLE_EQ(reports[0].location_confidence, 1.0);
  EXPECT_EQ(reports[1].person_id, "human11");
  EXPECT_EQ(reports[1].face_id, "faces");
  EXPECT_EQ(reports[1].voice_id, "voice");
  EXPECT_EQ(reports[1].location, Eigen::Vector2d(3.01, 1.0));  // the face before the body
  EXPECT_TRUE(registry.is_known(11));
  EXPECT_FALSE(registry.is_known(12));
}

TEST(PersonRegistry, LocationConfidenceFallsToZeroOverTenSeconds) {
  PersonRegistry registry({}, {}, core::Rng(1));
  world::WorldSnapshot snapshot = test::snapshot_with_ari(5.0);
  snapshot.humans = {human_at(10, 2.0, 0.0, 0.0)};
  std::vector<PersonReport> reports;
  registry.update(snapshot, nullptr, {body_of(10, "bodya", 2.0, 0.0)}, {}, {}, reports);
  // Unseen from t = 5 s: 1 - (t - 5) / 10, kept at the last place, links cleared.
  for (const auto& [t, expected] :
       {std::pair{7.5, 0.75}, std::pair{10.0, 0.5}, std::pair{14.0, 0.1}, std::pair{15.0, 0.0},
        std::pair{20.0, 0.0}}) {
    snapshot.time_s = t;
    registry.update(snapshot, nullptr, {}, {}, {}, reports);
    ASSERT_EQ(reports.size(), 1u);
    EXPECT_FALSE(reports[0].tracked);
    EXPECT_NEAR(reports[0].location_confidence, expected, 1e-12) << "t " << t;
    EXPECT_EQ(reports[0].location, Eigen::Vector2d(2.0, 0.0));
    EXPECT_EQ(reports[0].body_id, "");
    EXPECT_EQ(reports[0].engagement, EngagementLevel::kUnknown);
  }
  // A human removed from the world stays known and untracked.
  snapshot.humans.clear();
  registry.update(snapshot, nullptr, {}, {}, {}, reports);
  EXPECT_EQ(reports.size(), 1u);
}

TEST(PersonRegistry, EngagementComesFromThePerceivedFace) {
  EngagementConfig engagement;
  engagement.window_s = 1.0;
  PersonRegistry registry({}, engagement, core::Rng(1));
  world::WorldSnapshot snapshot = test::snapshot_with_ari();
  snapshot.humans = {human_at(10, 1.0, 0.0, core::kPi)};
  const AriSensors sensors = AriSensors::of(*snapshot.ari, PerceptionConfig());
  PerceivedFace face;
  face.human = 10;
  face.face_id = "faces";
  face.X_map_face = {{1.0, 0.0}, core::kPi};
  face.gaze_rad = core::kPi;  // looking at ARI, which looks at them
  std::vector<PersonReport> reports;
  for (int i = 0; i <= 12; ++i) {
    snapshot.time_s = 0.1 * i;
    registry.update(snapshot, &sensors, {}, {face}, {}, reports);
  }
  // 1.1196 m from the head camera (0.1196 m behind base_footprint, model/ari_sensor_geometry.hpp):
  // log(3.8804) / log(5) = 0.84 > 0.5.
  EXPECT_NEAR(reports.at(0).engagement_score, std::log(4.0 + 1.0 - 1.1196) / std::log(5.0), 1e-9);
  EXPECT_EQ(reports[0].engagement, EngagementLevel::kEngaged);
}

TEST(PersonRegistry, RandomIdStyleGivesSeededPermanentIdsOfNoHumanForm) {
  PersonConfig config;
  config.id_style = "random";
  auto ids_after_reset = [&](uint64_t seed) {
    PersonRegistry registry(config, {}, core::Rng(seed));
    world::WorldSnapshot snapshot = test::snapshot_with_ari(1.0);
    snapshot.humans = {human_at(10, 2.0, 0.0, 0.0), human_at(11, 3.0, 1.0, 0.0)};
    std::vector<PersonReport> reports;
    const std::vector<PerceivedBody> bodies = {body_of(10, "bodya", 2.0, 0.0),
                                               body_of(11, "bodyb", 3.0, 1.0)};
    registry.update(snapshot, nullptr, bodies, {}, {}, reports);
    std::vector<std::string> first = {reports[0].person_id, reports[1].person_id};
    registry.clear();  // a world reset: the same humans keep their ids
    snapshot.time_s = 0.5;
    registry.update(snapshot, nullptr, bodies, {}, {}, reports);
    EXPECT_EQ(first, (std::vector<std::string>{reports[0].person_id, reports[1].person_id}));
    EXPECT_EQ(registry.person_id(11), reports[1].person_id);
    return first;
  };
  const std::vector<std::string> ids = ids_after_reset(4);
  for (const std::string& id : ids) {
    // "anonymous_person_" and five lowercase letters, nothing of the human's number.
    ASSERT_EQ(id.size(), 22u) << id;
    EXPECT_EQ(id.rfind("anonymous_person_", 0), 0u) << id;
    EXPECT_EQ(id.find_first_of("0123456789"), std::string::npos) << id;
  }
  EXPECT_NE(ids[0], ids[1]);
  EXPECT_EQ(ids_after_reset(4), ids);
  EXPECT_NE(ids_after_reset(5), ids);
}

TEST(PersonRegistry, ForgottenAfterSixtySecondsUnseenAndBackUnderTheSameId) {
  PersonRegistry registry({}, {}, core::Rng(1));  // forget_after 60 s
  world::WorldSnapshot snapshot = test::snapshot_with_ari(5.0);
  snapshot.humans = {human_at(10, 2.0, 0.0, 0.0)};
  std::vector<PersonReport> reports;
  registry.update(snapshot, nullptr, {body_of(10, "bodya", 2.0, 0.0)}, {}, {}, reports);
  // Last seen at 5 s: known (confidence 0) up to 65 s, forgotten after.
  snapshot.time_s = 65.0;
  registry.update(snapshot, nullptr, {}, {}, {}, reports);
  ASSERT_EQ(reports.size(), 1u);
  EXPECT_EQ(reports[0].location_confidence, 0.0);
  snapshot.time_s = 65.05;
  registry.update(snapshot, nullptr, {}, {}, {}, reports);
  EXPECT_TRUE(reports.empty());
  EXPECT_FALSE(registry.is_known(10));
  EXPECT_EQ(registry.known_count(), 0u);
  // Seen again: a person again, "human10" as before, tracked from now.
  snapshot.time_s = 70.0;
  registry.update(snapshot, nullptr, {body_of(10, "bodyc", 2.0, 0.0)}, {}, {}, reports);
  ASSERT_EQ(reports.size(), 1u);
  EXPECT_EQ(reports[0].person_id, "human10");
  EXPECT_EQ(reports[0].body_id, "bodyc");
  EXPECT_DOUBLE_EQ(reports[0].location_confidence, 1.0);
}

TEST(PersonRegistry, KnownPersonsBoundedByWhoWasSeenInTheLastMinute) {
  // 1 000 humans pass one after the other, each seen for one frame, one every 2 s, and leave the
  // world: at most 60 s / 2 s + 1 = 31 are known at any time, not the 1 000 seen over the run.
  PersonConfig config;
  config.id_style = "random";
  PersonRegistry registry(config, {}, core::Rng(2));
  std::vector<PersonReport> reports;
  size_t most_known = 0;
  for (model::ObjectId human = 10; human < 1010; ++human) {
    world::WorldSnapshot snapshot = test::snapshot_with_ari(2.0 * (human - 10));
    snapshot.humans = {human_at(human, 2.0, 0.0, 0.0)};
    registry.update(snapshot, nullptr, {body_of(human, "bodya", 2.0, 0.0)}, {}, {}, reports);
    most_known = std::max(most_known, registry.known_count());
    EXPECT_LE(registry.remembered_id_count(), registry.known_count());
  }
  EXPECT_EQ(most_known, 31u);
  EXPECT_EQ(reports.size(), 31u);
}

TEST(PersonRegistry, RandomIdKeptWhileInTheWorldReleasedOnceGoneAndForgotten) {
  PersonConfig config;
  config.id_style = "random";
  config.forget_after_s = 20.0;
  PersonRegistry registry(config, {}, core::Rng(3));
  world::WorldSnapshot snapshot = test::snapshot_with_ari(0.0);
  snapshot.humans = {human_at(10, 2.0, 0.0, 0.0), human_at(11, 3.0, 1.0, 0.0)};
  std::vector<PersonReport> reports;
  registry.update(snapshot, nullptr,
                  {body_of(10, "bodya", 2.0, 0.0), body_of(11, "bodyb", 3.0, 1.0)}, {}, {},
                  reports);
  const std::string id10 = registry.person_id(10);
  const std::string id11 = registry.person_id(11);
  // Both unseen; human 11 leaves the world at 5 s. At 25.05 s both are forgotten: human 10's id
  // is kept (still in the world), human 11's released.
  snapshot.humans = {human_at(10, 2.0, 0.0, 0.0)};
  for (double t : {5.0, 25.05}) {
    snapshot.time_s = t;
    registry.update(snapshot, nullptr, {}, {}, {}, reports);
  }
  EXPECT_EQ(registry.known_count(), 0u);
  EXPECT_EQ(registry.remembered_id_count(), 1u);
  // Human 10 is seen again under its id; a new human 11 gets a new one.
  snapshot.time_s = 30.0;
  snapshot.humans = {human_at(10, 2.0, 0.0, 0.0), human_at(11, 3.0, 1.0, 0.0)};
  registry.update(snapshot, nullptr,
                  {body_of(10, "bodyc", 2.0, 0.0), body_of(11, "bodyd", 3.0, 1.0)}, {}, {},
                  reports);
  EXPECT_EQ(registry.person_id(10), id10);
  EXPECT_NE(registry.person_id(11), id11);
  EXPECT_EQ(registry.remembered_id_count(), 2u);
}

}  // namespace
}  // namespace ari_social_sim::perception
