#include <gtest/gtest.h>

#include "ari_social_sim/core/rng.hpp"
#include "ari_social_sim/scenario/person_identities.hpp"
#include "two_humans.hpp"

namespace ari_social_sim::scenario {
namespace {

const std::string kAnna = "anonymous_person_abcde";
const std::string kBert = "anonymous_person_fghij";
const std::string kCarl = "anonymous_person_klmno";

using test::two_humans;

PersonSighting body(const std::string& id, double x, double y) {
  return {id, {x, y}, true};
}
PersonSighting person_frame(const std::string& id, double x, double y) {
  return {id, {x, y}, false};
}

TEST(PersonIdentities, TwoPeopleOneMetreApartWithNoisySightings) {
  // 0.1 m per axis is perception's body noise at 3.5 m; a sighting would go to the wrong human
  // only with 0.5 m of error along the line between them, 5 standard deviations.
  const world::WorldSnapshot world = two_humans();
  PersonIdentities identities;
  core::Rng rng(3);
  for (int frame = 0; frame < 500; ++frame) {
    identities.update(world, {body(kBert, 3.0 + rng.normal(0.0, 0.1), 2.0 + rng.normal(0.0, 0.1)),
                              body(kAnna, 2.0 + rng.normal(0.0, 0.1), 2.0 + rng.normal(0.0, 0.1))});
    ASSERT_EQ(identities.person_of(10), kAnna) << "frame " << frame;
    ASSERT_EQ(identities.person_of(11), kBert) << "frame " << frame;
  }
  EXPECT_EQ(identities.human_of(kAnna), 10u);
  EXPECT_EQ(identities.human_of(kBert), 11u);
  EXPECT_EQ(identities.human_of(kCarl), std::nullopt);
}

TEST(PersonIdentities, NearestPairsGoFirst) {
  // Anna is 0.55 m from 10 and 0.45 m from 11, Bert 0.05 m from 11: Bert-11 is the nearest pair
  // and goes first, which leaves Anna to 10 although 11 is nearer to her.
  const world::WorldSnapshot world = two_humans();
  PersonIdentities identities;
  identities.update(world, {body(kAnna, 2.55, 2.0), body(kBert, 3.05, 2.0)});
  EXPECT_EQ(identities.person_of(10), kAnna);
  EXPECT_EQ(identities.person_of(11), kBert);
}

TEST(PersonIdentities, SwappedIdsFollowTheBodies) {
  const world::WorldSnapshot world = two_humans();
  PersonIdentities identities;
  identities.update(world, {body(kAnna, 2.0, 2.0), body(kBert, 3.0, 2.0)});
  // The tracker swapped the two ids: Anna is now the body at 11's place.
  identities.update(world, {body(kAnna, 3.05, 2.0), body(kBert, 1.95, 2.0)});
  EXPECT_EQ(identities.person_of(10), kBert);
  EXPECT_EQ(identities.person_of(11), kAnna);
  EXPECT_EQ(identities.human_of(kAnna), 11u);
  EXPECT_EQ(identities.human_of(kBert), 10u);
}

TEST(PersonIdentities, APersonUnseenForAWhileKeepsItsMatch) {
  world::WorldSnapshot world = two_humans();
  PersonIdentities identities;
  identities.update(world, {body(kAnna, 2.0, 2.0), body(kBert, 3.0, 2.0)});
  // Anna is hidden for 100 frames while human 10 walks 2 m away; Bert stays in view.
  for (int frame = 0; frame < 100; ++frame) {
    world.humans[0].pose.position.y() += 0.02;
    identities.update(world, {body(kBert, 3.0, 2.0)});
  }
  EXPECT_EQ(identities.person_of(10), kAnna);
  EXPECT_EQ(identities.human_of(kAnna), 10u);
  identities.update(world, {body(kAnna, 2.1, 4.0), body(kBert, 3.0, 2.0)});
  EXPECT_EQ(identities.person_of(10), kAnna);
  EXPECT_EQ(identities.person_of(11), kBert);
}

TEST(PersonIdentities, ANewPersonWhereAHumanIsReplacesTheOldMatch) {
  // A person manager that re-finds someone under a new id (an anonymous person per new body).
  const world::WorldSnapshot world = two_humans();
  PersonIdentities identities;
  identities.update(world, {body(kAnna, 2.0, 2.0)});
  identities.update(world, {body(kCarl, 2.1, 2.0)});
  EXPECT_EQ(identities.person_of(10), kCarl);
  EXPECT_EQ(identities.human_of(kCarl), 10u);
  EXPECT_EQ(identities.human_of(kAnna), std::nullopt);
}

TEST(PersonIdentities, ASpuriousPersonFarFromAnyoneIsNotMatched) {
  const world::WorldSnapshot world = two_humans();
  PersonIdentities identities;
  // 0.65 m below human 10 and 1.2 m from 11: beyond kMaxDistance_m (0.6 m) of both.
  identities.update(world, {body(kCarl, 2.0, 1.35)});
  EXPECT_EQ(identities.person_of(10), std::nullopt);
  EXPECT_EQ(identities.person_of(11), std::nullopt);
  EXPECT_EQ(identities.human_of(kCarl), std::nullopt);
  EXPECT_TRUE(identities.person_ids().empty());
  // 0.55 m away is within reach.
  identities.update(world, {body(kCarl, 2.0, 1.45)});
  EXPECT_EQ(identities.person_of(10), kCarl);
}

TEST(PersonIdentities, APersonFrameMatchesAfterBodies) {
  const world::WorldSnapshot world = two_humans();
  PersonIdentities identities;
  // Carl, heard only, is nearer human 10 (0.1 m) than Anna's body (0.3 m): the body wins, and
  // Carl, one person per human, is left unmatched.
  identities.update(world, {person_frame(kCarl, 2.1, 2.0), body(kAnna, 2.3, 2.0)});
  EXPECT_EQ(identities.person_of(10), kAnna);
  EXPECT_EQ(identities.human_of(kCarl), std::nullopt);
  // Anna out of view: a person frame alone does not undo her body's match.
  identities.update(world, {person_frame(kCarl, 2.1, 2.0)});
  EXPECT_EQ(identities.person_of(10), kAnna);
  // A human nobody's body has matched takes a person frame, until a body turns up.
  identities.update(world, {person_frame(kCarl, 3.1, 2.0)});
  EXPECT_EQ(identities.person_of(11), kCarl);
  identities.update(world, {body(kBert, 3.1, 2.0)});
  EXPECT_EQ(identities.person_of(11), kBert);
  EXPECT_EQ(identities.human_of(kCarl), std::nullopt);
  // Anna's person frame alone, now by 11, does not move her from 10 either.
  identities.update(world, {person_frame(kAnna, 3.0, 2.0)});
  EXPECT_EQ(identities.person_of(10), kAnna);
  EXPECT_EQ(identities.person_of(11), kBert);
}

TEST(PersonIdentities, AHumanWhoLeftTheWorldIsForgotten) {
  world::WorldSnapshot world = two_humans();
  PersonIdentities identities;
  identities.update(world, {body(kAnna, 2.0, 2.0), body(kBert, 3.0, 2.0)});
  world.humans.erase(world.humans.begin());
  identities.update(world, {});
  EXPECT_EQ(identities.person_of(10), std::nullopt);
  EXPECT_EQ(identities.human_of(kAnna), std::nullopt);
  EXPECT_EQ(identities.person_ids(), (std::map<model::ObjectId, std::string>{{11, kBert}}));
}

TEST(PersonIdentities, TiesGoToTheLowerIdsWhateverTheOrder) {
  // Halfway (2.5, 2) between the two humans, two sightings at equal distance from both.
  const world::WorldSnapshot world = two_humans();
  for (const bool reversed : {false, true}) {
    std::vector<PersonSighting> sightings = {body(kBert, 2.5, 2.0), body(kAnna, 2.5, 2.0)};
    if (reversed) {
      std::swap(sightings[0], sightings[1]);
    }
    PersonIdentities identities;
    identities.update(world, sightings);
    EXPECT_EQ(identities.person_of(10), kAnna);
    EXPECT_EQ(identities.person_of(11), kBert);
  }
}

TEST(SightingsOf, TrackedPersonsAtTheirBodyElseTheirPersonFrame) {
  perception::PerceptionFrame frame;
  perception::PerceivedBody seen;
  seen.body_id = "qwert";
  seen.X_map_body.position = {2.0, 3.0};
  frame.bodies.push_back(seen);
  perception::PersonReport with_body;
  with_body.person_id = kAnna;
  with_body.tracked = true;
  with_body.body_id = "qwert";
  with_body.location = {2.1, 3.1};  // the head, from the face: the body is preferred
  perception::PersonReport heard = with_body;
  heard.person_id = kBert;
  heard.body_id.clear();
  heard.location = {5.0, 1.0};
  perception::PersonReport gone = with_body;
  gone.person_id = kCarl;
  gone.tracked = false;
  frame.persons = {with_body, heard, gone};

  const std::vector<PersonSighting> sightings = sightings_of(frame);
  ASSERT_EQ(sightings.size(), 2u);
  EXPECT_EQ(sightings[0].person_id, kAnna);
  EXPECT_TRUE(sightings[0].from_body);
  EXPECT_EQ(sightings[0].position, Eigen::Vector2d(2.0, 3.0));
  EXPECT_EQ(sightings[1].person_id, kBert);
  EXPECT_FALSE(sightings[1].from_body);
  EXPECT_EQ(sightings[1].position, Eigen::Vector2d(5.0, 1.0));
}

}  // namespace
}  // namespace ari_social_sim::scenario
