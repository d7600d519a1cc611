#include "ari_social_sim/world/world_snapshot.hpp"

#include "ari_social_sim/world/simulation.hpp"

namespace ari_social_sim::world {

SpeechSnapshot snapshot_of(const SpeechGenerator& speech) {
  SpeechSnapshot snapshot;
  snapshot.act = speech.act();
  snapshot.content = speech.content();
  snapshot.current_word = speech.current_word();
  snapshot.word_index = static_cast<uint32_t>(speech.word_index());
  snapshot.is_speaking = speech.is_speaking();
  snapshot.start_s = speech.start_s();
  snapshot.words_per_minute = speech.words_per_minute();
  if (const SpeechRecord* previous = speech.previous()) {
    snapshot.previous_act = previous->act;
    snapshot.previous_content = previous->content;
  }
  return snapshot;
}

WorldSnapshot WorldSnapshot::of(const Simulation& simulation) {
  WorldSnapshot snapshot;
  snapshot.time_s = simulation.time_s();
  snapshot.step = simulation.step_count();
  if (const Ari* ari = simulation.ari()) {
    AriSnapshot a;
    a.id = ari->id();
    a.pose = ari->pose();
    a.linear_mps = ari->linear_mps();
    a.angular_rps = ari->angular_rps();
    a.head_pan_rad = ari->head().pan_rad();
    a.head_pan_velocity_rps = ari->head().pan_velocity_rps();
    a.speech = snapshot_of(ari->speech());
    snapshot.ari = a;
  }
  snapshot.humans.reserve(simulation.humans().size());
  for (const Human* human : simulation.humans()) {
    HumanSnapshot h;
    const HumanSpec& spec = human->spec();
    h.id = human->id();
    h.name = spec.name;
    h.role = spec.role;
    h.pose = human->pose();
    h.velocity_mps = human->velocity();
    h.angular_velocity_rps = human->angular_velocity();
    h.age_years = spec.age_years;
    h.gender = spec.gender;
    h.mask = spec.mask;
    h.emotion = spec.emotion;
    h.motion_mode = human->motion_mode();
    h.goal = human->goal();
    h.group_id = human->group_id();
    h.reaction = human->reaction_profile();
    const RobotReaction* reaction = human->reaction();
    if (reaction != nullptr && reaction->gaze()) {
      // The reaction to ARI overrides the person's own gaze while it lasts.
      const GazeEvent& gaze = *reaction->gaze();
      h.gaze = {gaze.target, gaze.direction_rad, gaze.since_s};
    } else if (const std::optional<GazeEvent>& talk = human->conversation_gaze()) {
      h.gaze = {talk->target, talk->direction_rad, talk->since_s};
    } else if (const GazeGenerator* gaze = human->gaze()) {
      h.gaze = {gaze->target(), gaze->direction_rad(), gaze->since_s()};
    } else {
      h.gaze.direction_rad = human->pose().theta;
    }
    h.head_pitch_rad = human->head_pitch_rad(snapshot.time_s);
    h.speech = snapshot_of(human->speech());
    h.posture = human->posture();
    h.walked_m = human->walked_m();
    snapshot.humans.push_back(std::move(h));
  }
  for (const GroupNavigation* group : simulation.groups()) {
    GroupSnapshot& g = snapshot.groups.emplace_back();
    g = {group->id(),           group->members(),
         group->centre(),       group->ospace_radius_m(),
         group->arrangement(),  group->heading_rad().value_or(0.0),
         group->robot_joining()};
    if (const GroupConversation* conversation = simulation.find_conversation(group->id())) {
      const ConversationFloor& floor = conversation->floor();
      g.converses = true;
      g.speaker = floor.speaker;
      g.addressee = floor.addressee;
      g.utterance_end_s = floor.utterance_end_s;
    }
  }
  for (const WalkingGroup* walking : simulation.walking_groups()) {
    snapshot.walking_groups.push_back({walking->id(), walking->members(), walking->formation(),
                                       walking->leader(), walking->heading_rad(),
                                       walking->spec().goal, walking->spec().on_arrival,
                                       walking->is_waiting(), walking->has_arrived()});
  }
  return snapshot;
}

}  // namespace ari_social_sim::world
