#include "ari_social_sim/scenario/person_identities.hpp"

#include <algorithm>
#include <set>
#include <tuple>

namespace ari_social_sim::scenario {
namespace {

// A sighting close enough to be a human.
struct Candidate {
  double distance_m{0.0};
  model::ObjectId human{model::kNoObject};
  const PersonSighting* sighting{nullptr};
};

}  // namespace

std::vector<PersonSighting> sightings_of(const perception::PerceptionFrame& frame) {
  std::vector<PersonSighting> sightings;
  for (const perception::PersonReport& person : frame.persons) {
    if (!person.tracked) {
      continue;
    }
    const auto body = std::find_if(
        frame.bodies.begin(), frame.bodies.end(),
        [&](const perception::PerceivedBody& b) { return b.body_id == person.body_id; });
    if (!person.body_id.empty() && body != frame.bodies.end()) {
      sightings.push_back({person.person_id, body->X_map_body.position, true});
    } else {
      sightings.push_back({person.person_id, person.location, false});
    }
  }
  return sightings;
}

void PersonIdentities::update(const world::WorldSnapshot& world,
                              const std::vector<PersonSighting>& sightings) {
  // Humans gone from the world are forgotten: their id may come back as someone else.
  for (auto match = matches_.begin(); match != matches_.end();) {
    const bool present =
        std::any_of(world.humans.begin(), world.humans.end(),
                    [&](const world::HumanSnapshot& h) { return h.id == match->first; });
    match = present ? std::next(match) : matches_.erase(match);
  }

  // Every pair close enough; bodies first, then nearest first, ties by ids.
  std::vector<Candidate> candidates;
  for (const world::HumanSnapshot& human : world.humans) {
    for (const PersonSighting& sighting : sightings) {
      const double distance_m = (sighting.position - human.pose.position).norm();
      if (distance_m <= kMaxDistance_m) {
        candidates.push_back({distance_m, human.id, &sighting});
      }
    }
  }
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
    const bool a_frame_only = !a.sighting->from_body, b_frame_only = !b.sighting->from_body;
    return std::tie(a_frame_only, a.distance_m, a.human, a.sighting->person_id) <
           std::tie(b_frame_only, b.distance_m, b.human, b.sighting->person_id);
  });

  // Greedy one-to-one assignment: each human and each person at most once per frame.
  std::set<model::ObjectId> assigned_humans;
  std::set<std::string> assigned_persons;
  for (const Candidate& c : candidates) {
    const std::string& person = c.sighting->person_id;
    if (assigned_humans.count(c.human) != 0 || assigned_persons.count(person) != 0) {
      continue;
    }
    const bool through_body = c.sighting->from_body;
    const auto current = matches_.find(c.human);
    if (!through_body) {
      // A person frame alone never undoes a body's match, on either side.
      const bool human_matched_by_body = current != matches_.end() &&
                                         current->second.through_body &&
                                         current->second.person_id != person;
      const std::optional<model::ObjectId> owner = human_of(person);
      const bool person_matched_by_body =
          owner && *owner != c.human && matches_.at(*owner).through_body;
      if (human_matched_by_body || person_matched_by_body) {
        continue;
      }
    }
    assigned_humans.insert(c.human);
    assigned_persons.insert(person);
    if (current != matches_.end() && current->second.person_id == person) {
      current->second.through_body = current->second.through_body || through_body;
      continue;
    }
    forget_person(person);
    matches_[c.human] = {person, through_body};
  }
}

std::optional<std::string> PersonIdentities::person_of(model::ObjectId human) const {
  const auto match = matches_.find(human);
  return match == matches_.end() ? std::nullopt
                                 : std::optional<std::string>(match->second.person_id);
}

std::optional<model::ObjectId> PersonIdentities::human_of(const std::string& person_id) const {
  for (const auto& [human, match] : matches_) {
    if (match.person_id == person_id) {
      return human;
    }
  }
  return std::nullopt;
}

std::map<model::ObjectId, std::string> PersonIdentities::person_ids() const {
  std::map<model::ObjectId, std::string> ids;
  for (const auto& [human, match] : matches_) {
    ids.emplace(human, match.person_id);
  }
  return ids;
}

void PersonIdentities::forget_person(const std::string& person_id) {
  for (auto match = matches_.begin(); match != matches_.end(); ++match) {
    if (match->second.person_id == person_id) {
      matches_.erase(match);
      return;
    }
  }
}

}  // namespace ari_social_sim::scenario
