#include <gtest/gtest.h>

#include "ari_social_sim/dialogue/rule_policy.hpp"
#include "test_helpers.hpp"

namespace ari_social_sim::dialogue {
namespace {

using testing::config_path;

Perception heard(const std::string& acts, const std::string& addressee = kRobot) {
  Perception p;
  p.speaker = "patient";
  p.addressees = {addressee};
  p.acts = parse_acts(acts, "t");
  return p;
}

TEST(RulePolicy, GreetsAnswersDeclinesAndWaits) {
  const Domain domain = Domain::load(config_path("hospital_domain.yaml"));
  RulePolicy policy(domain);
  Observation observation;
  EXPECT_EQ(acts_to_string(policy.act(observation).acts),
            "greet(); inform(ari(name)); offer-help()");
  observation.robot_turn = 1;
  observation.heard = {heard("request(location(toilet))")};
  EXPECT_EQ(acts_to_string(policy.act(observation).acts), "inform(directions(toilet))");
  observation.heard = {heard("request(appt(time))")};  // ARI does not know
  EXPECT_EQ(acts_to_string(policy.act(observation).acts), "cant-help()");
  observation.heard = {heard("request(location(moon))")};  // not in the domain
  EXPECT_EQ(acts_to_string(policy.act(observation).acts), "cant-help()");
  observation.heard = {heard("r-repet(directions(toilet))")};
  EXPECT_EQ(acts_to_string(policy.act(observation).acts), "cant-help()");  // repeats its last
  observation.heard = {heard("bye()")};
  EXPECT_EQ(acts_to_string(policy.act(observation).acts), "thank(); bye()");
  // Said to the companion, or dropped: ARI stays silent.
  observation.heard = {heard("request(location(toilet))", "companion")};
  EXPECT_TRUE(policy.act(observation).acts.empty());
  Perception dropped = heard("request(location(toilet))");
  dropped.dropped = true;
  observation.heard = {dropped};
  EXPECT_TRUE(policy.act(observation).acts.empty());
}

}  // namespace
}  // namespace ari_social_sim::dialogue
