// Wire compatibility of our copies of upstream ROS types.
//
// ROS 1 peers accept a connection when the two sides' MD5 sums are equal (docs/messages.md), so
// each copy in msg/, srv/ and action/ must hash exactly like the upstream type it mirrors. The
// expected sums are those of the upstream definitions (hri_msgs 0.9.0; control_msgs 1.5.x,
// pal_interaction_msgs 0.16.0, play_motion_msgs 0.4.x: Upstream messages in docs/references.md)
// as genmsg computes them. Only roscpp's header-only traits are used.

#include <gtest/gtest.h>
#include <ros/message_traits.h>
#include <ros/service_traits.h>

#include <ostream>
#include <string>
#include <vector>

#include "actionlib_msgs/GoalID.h"
#include "actionlib_msgs/GoalStatus.h"
#include "actionlib_msgs/GoalStatusArray.h"
#include "ari_social_sim/AudioData.h"
#include "ari_social_sim/AudioFeatures.h"
#include "ari_social_sim/BodyPosture.h"
#include "ari_social_sim/EngagementLevel.h"
#include "ari_social_sim/Expression.h"
#include "ari_social_sim/FacialActionUnits.h"
#include "ari_social_sim/FacialLandmarks.h"
#include "ari_social_sim/FollowJointTrajectoryAction.h"
#include "ari_social_sim/Gaze.h"
#include "ari_social_sim/Gesture.h"
#include "ari_social_sim/Group.h"
#include "ari_social_sim/I18nArgument.h"
#include "ari_social_sim/I18nText.h"
#include "ari_social_sim/IdsList.h"
#include "ari_social_sim/IdsMatch.h"
#include "ari_social_sim/JointTolerance.h"
#include "ari_social_sim/JointTrajectoryControllerState.h"
#include "ari_social_sim/LiveSpeech.h"
#include "ari_social_sim/NormalizedPointOfInterest2D.h"
#include "ari_social_sim/NormalizedPointOfInterest2DStamped.h"
#include "ari_social_sim/NormalizedRegionOfInterest2D.h"
#include "ari_social_sim/PlayMotionAction.h"
#include "ari_social_sim/PointHeadAction.h"
#include "ari_social_sim/QueryTrajectoryState.h"
#include "ari_social_sim/Skeleton2D.h"
#include "ari_social_sim/SoftBiometrics.h"
#include "ari_social_sim/TtsAction.h"
#include "ari_social_sim/TtsMark.h"
#include "ari_social_sim/TtsText.h"
#include "geometry_msgs/PointStamped.h"
#include "geometry_msgs/Vector3.h"
#include "std_msgs/Header.h"
#include "trajectory_msgs/JointTrajectory.h"
#include "trajectory_msgs/JointTrajectoryPoint.h"

namespace {

// One row of the tables below: the upstream type, its published MD5, and the MD5 of our copy.
struct WireType {
  std::string upstream;
  std::string expected_md5;
  std::string our_md5;
};

// gtest prints the parameter in a failing test's name line; make it the upstream type.
void PrintTo(const WireType& row, std::ostream* os) {
  *os << row.upstream;
}

template <class M>
std::string message_md5() {
  return ros::message_traits::MD5Sum<M>::value();
}

template <class S>
std::string service_md5() {
  return ros::service_traits::MD5Sum<S>::value();
}

namespace a = ari_social_sim;

// hri_msgs 0.9.0 (= master).
const std::vector<WireType> kHriMsgs = {
    {"hri_msgs/AudioFeatures", "1942f4cd8b6bb147f1ccb9aded9b6535", message_md5<a::AudioFeatures>()},
    {"hri_msgs/BodyPosture", "52f95070a71954a985e0ab92dd4d4eb9", message_md5<a::BodyPosture>()},
    {"hri_msgs/EngagementLevel", "98693df082bea7da40fa598b187373d9",
     message_md5<a::EngagementLevel>()},
    {"hri_msgs/Expression", "c0f698742672d3238cdc31c07c7d835b", message_md5<a::Expression>()},
    {"hri_msgs/FacialActionUnits", "51deeb0e003e99c3f3ea2a5073d9d710",
     message_md5<a::FacialActionUnits>()},
    {"hri_msgs/FacialLandmarks", "c779d9fd02c1af8ab6a1712921ab9da5",
     message_md5<a::FacialLandmarks>()},
    {"hri_msgs/Gaze", "1408dc110169ebd2a0cd704f3af52beb", message_md5<a::Gaze>()},
    {"hri_msgs/Gesture", "c64cc745a3c18d0a7abe6aed5be4f345", message_md5<a::Gesture>()},
    {"hri_msgs/Group", "76be953e6ddf78f60b879c220d0a3c32", message_md5<a::Group>()},
    {"hri_msgs/IdsList", "84a63f55b5676f78b625e8a8bb809fe5", message_md5<a::IdsList>()},
    {"hri_msgs/IdsMatch", "47ee5557c84afd004bec4ac7f5fa56f7", message_md5<a::IdsMatch>()},
    {"hri_msgs/LiveSpeech", "691fad051ce92a736be494854c99c2d5", message_md5<a::LiveSpeech>()},
    {"hri_msgs/NormalizedPointOfInterest2D", "eb224da30b2d872f41cf40e039cdb0d6",
     message_md5<a::NormalizedPointOfInterest2D>()},
    {"hri_msgs/NormalizedPointOfInterest2DStamped", "f00d620d5791659f1cba63fdcb50f444",
     message_md5<a::NormalizedPointOfInterest2DStamped>()},
    {"hri_msgs/NormalizedRegionOfInterest2D", "33eb96af02d4b1dd1457132b5c2149c2",
     message_md5<a::NormalizedRegionOfInterest2D>()},
    {"hri_msgs/Skeleton2D", "efedc2dc59671380a1d9b497f0740be4", message_md5<a::Skeleton2D>()},
    {"hri_msgs/SoftBiometrics", "791877398420c10707c4d9a832b0e6ad",
     message_md5<a::SoftBiometrics>()},
};

// control_msgs 1.5.x.
const std::vector<WireType> kControlMsgs = {
    {"control_msgs/FollowJointTrajectoryAction", "bc4f9b743838566551c0390c65f1a248",
     message_md5<a::FollowJointTrajectoryAction>()},
    {"control_msgs/FollowJointTrajectoryActionGoal", "cff5c1d533bf2f82dd0138d57f4304bb",
     message_md5<a::FollowJointTrajectoryActionGoal>()},
    {"control_msgs/FollowJointTrajectoryActionResult", "c4fb3b000dc9da4fd99699380efcc5d9",
     message_md5<a::FollowJointTrajectoryActionResult>()},
    {"control_msgs/FollowJointTrajectoryActionFeedback", "d8920dc4eae9fc107e00999cce4be641",
     message_md5<a::FollowJointTrajectoryActionFeedback>()},
    {"control_msgs/FollowJointTrajectoryGoal", "69636787b6ecbde4d61d711979bc7ecb",
     message_md5<a::FollowJointTrajectoryGoal>()},
    {"control_msgs/FollowJointTrajectoryResult", "493383b18409bfb604b4e26c676401d2",
     message_md5<a::FollowJointTrajectoryResult>()},
    {"control_msgs/FollowJointTrajectoryFeedback", "10817c60c2486ef6b33e97dcd87f4474",
     message_md5<a::FollowJointTrajectoryFeedback>()},
    {"control_msgs/JointTrajectoryControllerState", "10817c60c2486ef6b33e97dcd87f4474",
     message_md5<a::JointTrajectoryControllerState>()},
    {"control_msgs/JointTolerance", "f544fe9c16cf04547e135dd6063ff5be",
     message_md5<a::JointTolerance>()},
    {"control_msgs/PointHeadAction", "7252920f1243de1b741f14f214125371",
     message_md5<a::PointHeadAction>()},
    {"control_msgs/PointHeadActionGoal", "b53a8323d0ba7b310ba17a2d3a82a6b8",
     message_md5<a::PointHeadActionGoal>()},
    {"control_msgs/PointHeadActionResult", "1eb06eeff08fa7ea874431638cb52332",
     message_md5<a::PointHeadActionResult>()},
    {"control_msgs/PointHeadActionFeedback", "33c9244957176bbba97dd641119e8460",
     message_md5<a::PointHeadActionFeedback>()},
    {"control_msgs/PointHeadGoal", "8b92b1cd5e06c8a94c917dc3209a4c1d",
     message_md5<a::PointHeadGoal>()},
    {"control_msgs/PointHeadResult", "d41d8cd98f00b204e9800998ecf8427e",
     message_md5<a::PointHeadResult>()},
    {"control_msgs/PointHeadFeedback", "cce80d27fd763682da8805a73316cab4",
     message_md5<a::PointHeadFeedback>()},
    {"control_msgs/QueryTrajectoryState (service)", "ec93cdecbd8062d761aa52b7c90cd44b",
     service_md5<a::QueryTrajectoryState>()},
    {"control_msgs/QueryTrajectoryStateRequest", "556a4fb76023a469987922359d08a844",
     message_md5<a::QueryTrajectoryStateRequest>()},
    {"control_msgs/QueryTrajectoryStateResponse", "1f1a6554ad060f44d013e71868403c1a",
     message_md5<a::QueryTrajectoryStateResponse>()},
};

// pal_interaction_msgs 0.16.0 (Tts with visemes).
const std::vector<WireType> kPalInteractionMsgs = {
    {"pal_interaction_msgs/TtsAction", "973ac2281b44b7ee789af997a9ce140c",
     message_md5<a::TtsAction>()},
    {"pal_interaction_msgs/TtsActionGoal", "3bccf3a2c5d1d54cc7b0d11a481421eb",
     message_md5<a::TtsActionGoal>()},
    {"pal_interaction_msgs/TtsActionResult", "221e53027c3cef1d5af46761df78a1a3",
     message_md5<a::TtsActionResult>()},
    {"pal_interaction_msgs/TtsActionFeedback", "82b626fa6d80168af2669a8a59dc7d3c",
     message_md5<a::TtsActionFeedback>()},
    {"pal_interaction_msgs/TtsGoal", "9c88bf4a4d119474b8ae97c98892bc78", message_md5<a::TtsGoal>()},
    {"pal_interaction_msgs/TtsResult", "e83da3aebdbed111fd63209d97dcddcd",
     message_md5<a::TtsResult>()},
    {"pal_interaction_msgs/TtsFeedback", "05870cd8b62fcb00e76ae3889c0ed8f1",
     message_md5<a::TtsFeedback>()},
    {"pal_interaction_msgs/I18nText", "855c0cd82eb6837b039ea45087975cc2",
     message_md5<a::I18nText>()},
    {"pal_interaction_msgs/I18nArgument", "5c584e5b757794e1616ca51692089746",
     message_md5<a::I18nArgument>()},
    {"pal_interaction_msgs/TtsText", "a42001bb3ccbf1a914b618f34087dc37", message_md5<a::TtsText>()},
    {"pal_interaction_msgs/TtsMark", "10ae9a83cac56ac1660df7e26eabeac9", message_md5<a::TtsMark>()},
};

// play_motion_msgs 0.4.x.
const std::vector<WireType> kPlayMotionMsgs = {
    {"play_motion_msgs/PlayMotionAction", "b18530db1ae596c4c0ca2ede0819fc9e",
     message_md5<a::PlayMotionAction>()},
    {"play_motion_msgs/PlayMotionActionGoal", "ce0017b9347897304a66c70a78c9408b",
     message_md5<a::PlayMotionActionGoal>()},
    {"play_motion_msgs/PlayMotionActionResult", "99680b95d3bd3f96e403ed053918b8d1",
     message_md5<a::PlayMotionActionResult>()},
    {"play_motion_msgs/PlayMotionActionFeedback", "aae20e09065c3809e8a8e87c4c8953fd",
     message_md5<a::PlayMotionActionFeedback>()},
    {"play_motion_msgs/PlayMotionGoal", "803175b562438759e071140087987d02",
     message_md5<a::PlayMotionGoal>()},
    {"play_motion_msgs/PlayMotionResult", "5560cb9a7211cb4b5a730f6f07ec124b",
     message_md5<a::PlayMotionResult>()},
    {"play_motion_msgs/PlayMotionFeedback", "d41d8cd98f00b204e9800998ecf8427e",
     message_md5<a::PlayMotionFeedback>()},
};

// audio_common_msgs 0.3.x: the audio driver's chunks.
const std::vector<WireType> kAudioCommonMsgs = {
    {"audio_common_msgs/AudioData", "f43a8e1b362b75baa741461b46adc7e0",
     message_md5<a::AudioData>()},
};

// The dependencies Debian does package: the Debian types our copies
// embed. If one of them drifted from the sums upstream was computed against, every copy that
// nests it would stop connecting even with correct field lists.
const std::vector<WireType> kDebianDependencies = {
    {"std_msgs/Header", "2176decaecbce78abc3b96ef049fabed", message_md5<std_msgs::Header>()},
    {"actionlib_msgs/GoalID", "302881f31927c1df708a2dbab0e80ee8",
     message_md5<actionlib_msgs::GoalID>()},
    {"actionlib_msgs/GoalStatus", "d388f9b87b3c471f784434d671988d4a",
     message_md5<actionlib_msgs::GoalStatus>()},
    {"actionlib_msgs/GoalStatusArray", "8b2b82f13216d0a8ea88bd3af735e619",
     message_md5<actionlib_msgs::GoalStatusArray>()},
    {"trajectory_msgs/JointTrajectory", "65b4f94a94d1ed67169da35a02f33d3f",
     message_md5<trajectory_msgs::JointTrajectory>()},
    {"trajectory_msgs/JointTrajectoryPoint", "f3cd1e1c4d320c79d6985c904ae5dcd3",
     message_md5<trajectory_msgs::JointTrajectoryPoint>()},
    {"geometry_msgs/PointStamped", "c63aecb41bfdfd6b7e1fac37c7cbe7bf",
     message_md5<geometry_msgs::PointStamped>()},
    {"geometry_msgs/Vector3", "4a842b65f413084dc2b10fb484ea7f17",
     message_md5<geometry_msgs::Vector3>()},
};

class WireMd5 : public ::testing::TestWithParam<WireType> {};

TEST_P(WireMd5, EqualsUpstream) {
  const WireType& row = GetParam();
  EXPECT_EQ(row.our_md5, row.expected_md5)
      << "our copy of " << row.upstream << " would not connect to the real type";
}

// Test names such as WireMd5/HriMsgs.EqualsUpstream/IdsList: the upstream type without package.
std::string type_name(const ::testing::TestParamInfo<WireType>& info) {
  std::string name = info.param.upstream.substr(info.param.upstream.find('/') + 1);
  const std::size_t space = name.find(' ');
  return space == std::string::npos ? name : name.substr(0, space) + "Service";
}

INSTANTIATE_TEST_SUITE_P(HriMsgs, WireMd5, ::testing::ValuesIn(kHriMsgs), type_name);
INSTANTIATE_TEST_SUITE_P(ControlMsgs, WireMd5, ::testing::ValuesIn(kControlMsgs), type_name);
INSTANTIATE_TEST_SUITE_P(PalInteractionMsgs, WireMd5, ::testing::ValuesIn(kPalInteractionMsgs),
                         type_name);
INSTANTIATE_TEST_SUITE_P(PlayMotionMsgs, WireMd5, ::testing::ValuesIn(kPlayMotionMsgs), type_name);
INSTANTIATE_TEST_SUITE_P(AudioCommonMsgs, WireMd5, ::testing::ValuesIn(kAudioCommonMsgs),
                         type_name);
INSTANTIATE_TEST_SUITE_P(DebianDependencies, WireMd5, ::testing::ValuesIn(kDebianDependencies),
                         type_name);

// The tables above hold 17 + 19 + 11 + 7 + 1 + 8 rows; a row dropped by an edit must not pass
// silently.
TEST(WireMd5Tables, CoverEverySpecRow) {
  EXPECT_EQ(kHriMsgs.size(), 17u);
  EXPECT_EQ(kControlMsgs.size(), 19u);
  EXPECT_EQ(kPalInteractionMsgs.size(), 11u);
  EXPECT_EQ(kPlayMotionMsgs.size(), 7u);
  EXPECT_EQ(kAudioCommonMsgs.size(), 1u);
  EXPECT_EQ(kDebianDependencies.size(), 8u);
}

// The method itself: the same traits reproduce the known-good sum of a Debian type.
TEST(WireMd5Method, ReproducesStdMsgsHeader) {
  EXPECT_EQ(message_md5<std_msgs::Header>(), "2176decaecbce78abc3b96ef049fabed");
}

// What differs from upstream on the wire: the type name in the connection header (never compared
// by roscpp or rospy when the MD5s match; see docs/messages.md).
TEST(WireTypeName, IsOurPackageNotUpstream) {
  EXPECT_STREQ(ros::message_traits::DataType<a::IdsList>::value(), "ari_social_sim/IdsList");
  EXPECT_STREQ(ros::message_traits::DataType<a::TtsActionGoal>::value(),
               "ari_social_sim/TtsActionGoal");
  EXPECT_STREQ(ros::service_traits::DataType<a::QueryTrajectoryState>::value(),
               "ari_social_sim/QueryTrajectoryState");
}

// ROS 1 genmsg keeps the double quotes of a string constant as part of its value (ROS 1 wire
// protocol in docs/references.md), so the constant is 7 characters for "happy"; ROS 2 strips
// them. Pinned so a consumer comparing against Expression::HAPPY sees the same value as with
// upstream hri_msgs.
TEST(ExpressionConstants, KeepTheirQuotesAsInRos1) {
  EXPECT_EQ(a::Expression::HAPPY, "\"happy\"");
  EXPECT_EQ(a::Expression::HAPPY.size(), 7u);  // 5 letters + 2 quotes
  EXPECT_EQ(a::Expression::EXCITED, "\"excited\"");
}

}  // namespace
