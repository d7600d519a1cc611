#pragma once

#include <array>
#include <cstdint>
#include <string_view>

#include "ari_social_sim/core/check.hpp"
#include "ari_social_sim/core/rng.hpp"

// Every random stream of the simulator, in one registry. A run derives all its generators from one
// seed (an episode gives the same seed to the world, the perception, the script and the
// dialogue), so two components that used the same stream number would draw the same numbers:
// people whose gaze repeats the perception's misses, say. Each component names its block here and
// draws through rng_for; test_rng_streams checks that no two blocks overlap.

namespace ari_social_sim::core {

/// A block of streams: Rng::for_stream(seed, first + index) for index in [0, count). A single
/// stream has count 1; a family (one stream per human, per group member, ...) one per index.
struct RngStreams {
  std::string_view name;
  std::string_view component;  // who draws from it
  uint64_t first{0};
  uint64_t count{1};
};

namespace rng_streams {

// One stream per object id (model::ObjectId is 32-bit).
inline constexpr uint64_t kPerObjectId = uint64_t{1} << 32;
// The single streams and the small families sit above every per-id family, keeping the number
// they had when each component numbered its own (perception 1-5, ...).
inline constexpr uint64_t kSingles = uint64_t{1} << 40;

// World (world/): the humans' gaze and reactions to ARI, the group members' manners.
inline constexpr RngStreams kHumanGaze{"human_gaze", "world::Simulation, a human's gaze by id", 0,
                                       kPerObjectId};
inline constexpr RngStreams kHumanReaction{"human_reaction",
                                           "world::Simulation, a human's reaction to ARI by id",
                                           kPerObjectId, kPerObjectId};
inline constexpr RngStreams kGroupConversation{
    "group_conversation", "world::GroupConversation, a group's turn-taking and gaze by group id",
    4 * kPerObjectId, kPerObjectId};
inline constexpr RngStreams kGroupNods{
    "group_nods", "world::GroupConversation, a group's listeners' nods by group id",
    6 * kPerObjectId, kPerObjectId};
inline constexpr RngStreams kGroupTurnover{
    "group_turnover", "world::GroupTurnover, a group's departures and arrivals by group id",
    5 * kPerObjectId, kPerObjectId};
/// Index (group id << 24) + member id.
inline constexpr RngStreams kGroupStance{
    "group_stance", "world::MemberManner, a member's stance and spacing by group and id",
    uint64_t{1} << 48, uint64_t{1} << 56};
/// Index (group id << 24) + member id: a member's shifts of place and facing over time.
inline constexpr RngStreams kGroupShift{
    "group_shift", "world::MemberManner, a member's shifts and turns by group and id",
    uint64_t{1} << 57, uint64_t{1} << 56};

// Physics (physics/).
inline constexpr RngStreams kHumanAppearance{"human_appearance",
                                             "rendering::appearance_of, a human's looks by id",
                                             2 * kPerObjectId, kPerObjectId};
inline constexpr RngStreams kHumanWeightShifts{
    "human_weight_shifts", "rendering::WeightShifts, a standing human's weight shifts by id",
    7 * kPerObjectId, kPerObjectId};
inline constexpr RngStreams kHumanVoice{"human_voice", "audio::voice_for, a human's voice by id",
                                        3 * kPerObjectId, kPerObjectId};
inline constexpr RngStreams kRoomNoise{
    "room_noise", "audio::ArrayMixer, the diffuse background noise", kSingles + 13};
inline constexpr RngStreams kImuNoise{"imu_noise", "physics::AriPhysics, the torso IMU's noise",
                                      kSingles + 12};
// Rendering (rendering/): each camera's sensor noise and white balance, by camera index.
inline constexpr RngStreams kCameraSensor{
    "camera_sensor", "rendering::CameraSensor, a camera's noise and white balance by index",
    kSingles + 16, 16};

// Perception (perception/ and hri_perception_node): one stream per error model, so that switching
// one off leaves the draws of the others unchanged.
inline constexpr RngStreams kPerceptionTransientIds{
    "perception_transient_ids", "perception::PerceptionPipeline, new track ids", kSingles + 1};
inline constexpr RngStreams kPerceptionBodies{
    "perception_bodies", "perception::PerceptionPipeline, body detection errors", kSingles + 2};
inline constexpr RngStreams kPerceptionFaces{
    "perception_faces", "perception::PerceptionPipeline, face detection errors", kSingles + 3};
inline constexpr RngStreams kPerceptionSpeech{
    "perception_speech", "perception::PerceptionPipeline, speech recognition errors", kSingles + 4};
inline constexpr RngStreams kPerceptionPersonIds{
    "perception_person_ids", "perception::PerceptionPipeline, person ids", kSingles + 5};
inline constexpr RngStreams kPerceptionMatcher{
    "perception_matcher", "hri_perception_node, the detectors' candidate matcher", kSingles + 6};

// Learning (learning/).
inline constexpr RngStreams kNavEpisodeType{
    "nav_episode_type", "learning::NavEnv, the group size of a join episode", kSingles + 7};
inline constexpr RngStreams kNavWalkers{"nav_walkers", "learning::NavEnv, the passers-by",
                                        kSingles + 11};
/// Index (episode type << 20) + index within the type.
inline constexpr RngStreams kNavigationEpisodes{
    "navigation_episodes", "learning::make_episode, an episode's seed by type and index",
    uint64_t{1} << 42, uint64_t{1} << 28};

// Scenarios (scenario/).
inline constexpr RngStreams kRandomGroups{
    "random_groups", "scenario::ScriptRunner, a random group's members by index",
    kSingles + 0x5ce0a210, uint64_t{1} << 16};
inline constexpr RngStreams kRandomGroupScene{
    "random_group_scene", "scenario::random_group_scene, the scene's groups and places",
    kSingles + 0x5ce9e0a7};
inline constexpr RngStreams kConversation{
    "conversation", "scenario::ScriptRunner, the scripted conversation's seed",
    kSingles + 0xc0417e75};

// Dialogue (dialogue/).
inline constexpr RngStreams kDialogueEpisodes{
    "dialogue_episodes", "dialogue::episode_seed, a dialogue's seed by index in its run",
    uint64_t{1} << 41, kPerObjectId};

/// Every block, for the overlap test and the documentation.
inline constexpr std::array kAll{kHumanVoice,        kRoomNoise,
                                 kHumanGaze,         kHumanReaction,
                                 kGroupStance,       kGroupConversation,
                                 kGroupShift,        kGroupTurnover,
                                 kGroupNods,         kHumanAppearance,
                                 kHumanWeightShifts, kImuNoise,
                                 kCameraSensor,      kPerceptionTransientIds,
                                 kPerceptionBodies,  kPerceptionFaces,
                                 kPerceptionSpeech,  kPerceptionPersonIds,
                                 kPerceptionMatcher, kNavEpisodeType,
                                 kNavWalkers,        kNavigationEpisodes,
                                 kRandomGroups,      kRandomGroupScene,
                                 kConversation,      kDialogueEpisodes};

}  // namespace rng_streams

/// The generator of stream `index` of `streams` for `seed`. Precondition: index < streams.count.
inline Rng rng_for(uint64_t seed, const RngStreams& streams, uint64_t index = 0) {
  ARI_CHECK(index < streams.count);
  return Rng::for_stream(seed, streams.first + index);
}

}  // namespace ari_social_sim::core
