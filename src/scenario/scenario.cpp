#include "ari_social_sim/scenario/scenario.hpp"

#include <algorithm>
#include <filesystem>
#include <initializer_list>
#include <set>
#include <sstream>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/scenario/heard_lines.hpp"
#include "ari_social_sim/scenario/script_time_limit.hpp"

namespace ari_social_sim::scenario {
namespace {

const std::vector<std::string> kConditionTypes = {
    "distance_below", "distance_above",  "speech_finished",   "goal_reached", "navigation_failed",
    "time_elapsed",   "perceived_group", "dialogue_finished", "heard",        "floor_free",
    "addressed",      "not_understood"};
const std::vector<std::string> kActionTypes = {"say",
                                               "set_goal",
                                               "approach",
                                               "join_group",
                                               "cancel_navigation",
                                               "add_human",
                                               "remove_human",
                                               "create_group",
                                               "create_walking_group",
                                               "add_group_members",
                                               "set_group_centre",
                                               "leave_group",
                                               "set_group_arrangement",
                                               "set_posture",
                                               "converse",
                                               "stop"};

std::string one_of(const std::vector<std::string>& names) {
  std::string text = "one of ";
  for (size_t i = 0; i < names.size(); ++i) {
    text += (i == 0 ? "" : ", ") + names[i];
  }
  return text;
}

// Reads `type` and checks it is one of `types`.
std::string read_type(const core::YamlMap& entry, const std::vector<std::string>& types) {
  std::string type = entry.required<std::string>("type");
  if (std::find(types.begin(), types.end(), type) == types.end()) {
    entry.fail("type", one_of(types), "'" + type + "'");
  }
  return type;
}

std::string read_text(const core::YamlMap& map, const std::string& key) {
  std::string text = map.required<std::string>(key);
  if (text.find_first_not_of(" \t\n") == std::string::npos) {
    map.fail(key, "a non-empty string", "'" + text + "'");
  }
  return text;
}

model::ObjectId read_id(const core::YamlMap& map, const std::string& key) {
  return map.required<unsigned>(key, core::positive());
}

// A required field that names one of `choices`, e.g. `arrangement: expected circle, vis-a-vis,
// l-shape or side-by-side, got 'ring'`.
template <class Choices>
auto read_named_choice(const core::YamlMap& map, const std::string& key, const Choices& choices) {
  const std::string name = map.required<std::string>(key);
  if (!core::names_a_choice(name, choices)) {
    map.fail(key, core::choice_names(choices), "'" + name + "'");
  }
  return core::parse_choice(name, choices, key);
}

// A human (never ARI) named by id.
model::ObjectId read_human_ref(const core::YamlMap& map, const std::string& key) {
  const AgentRef ref = read_agent_ref(map, key);
  if (ref.is_ari()) {
    map.fail(key, "a human id", "ari");
  }
  return ref.human_id;
}

// What the script may refer to, for the checks that follow reading: the scene's humans and
// groups plus those the script itself adds.
struct KnownIds {
  bool has_ari{false};
  model::ObjectId ari_id{model::kNoObject};
  std::set<model::ObjectId> statics;  // walls and furniture
  std::set<model::ObjectId> humans;
  std::set<model::ObjectId> groups;
};

// A reference to check once every state is read (a human may be added by a later state).
struct PendingCheck {
  enum class Kind { kAgent, kGroup } kind;
  model::ObjectId id;  // for agents kNoObject means ARI
  std::string field;   // `file: script.states[0].enter[1].speaker`
};

class ScriptReader {
 public:
  explicit ScriptReader(const world::Scene& scene) {
    known_.has_ari = scene.ari.has_value();
    if (scene.ari) {
      known_.ari_id = scene.ari->id;
    }
    for (const model::StaticObject& object : scene.world.objects) {
      known_.statics.insert(object.id);
    }
    for (const world::HumanSpec& human : scene.humans) {
      known_.humans.insert(human.id);
    }
    for (const world::GroupSpec& group : scene.groups) {
      known_.groups.insert(group.id);
    }
    for (const world::WalkingGroupSpec& group : scene.walking_groups) {
      known_.groups.insert(group.id);
    }
  }

  Script read(const core::YamlMap& map) {
    Script script;
    script.time_limit_s = map.required<double>("time_limit", script_time_limit_bounds());
    for (const core::YamlMap& entry : map.list("random_groups", true)) {
      script.random_groups.push_back(read_random_group(entry));
    }
    script.start = map.required<std::string>("start");
    const std::vector<core::YamlMap> states = map.list("states");
    if (states.empty()) {
      map.fail("states", "at least one state", "an empty list");
    }
    std::vector<std::string> next_fields;  // where each transition's `next` was written
    for (const core::YamlMap& entry : states) {
      script.states.push_back(read_state(entry, next_fields));
    }
    map.finish();
    check_names(script, map, next_fields);
    check_references();
    check_heard_acts(script);
    return script;
  }

 private:
  State read_state(const core::YamlMap& entry, std::vector<std::string>& next_fields) {
    State state;
    state.name = read_text(entry, "name");
    for (const core::YamlMap& action : entry.list("enter", true)) {
      state.on_enter.push_back(read_action(action));
    }
    for (const core::YamlMap& item : entry.list("transitions", true)) {
      Transition transition;
      transition.field = item.where();
      for (const core::YamlMap& condition : item.list("when")) {
        transition.when.push_back(read_condition(condition));
      }
      for (const core::YamlMap& action : item.list("do", true)) {
        transition.actions.push_back(read_action(action));
      }
      const bool stops =
          std::any_of(transition.actions.begin(), transition.actions.end(),
                      [](const Action& a) { return std::holds_alternative<StopAction>(a); });
      if (stops && item.has("next")) {
        item.fail("next", "no next state after a stop action",
                  "'" + item.required<std::string>("next") + "'");
      }
      if (!stops) {
        transition.next = item.required<std::string>("next");
      }
      next_fields.push_back(item.field_name("next"));
      item.finish();
      state.transitions.push_back(std::move(transition));
    }
    entry.finish();
    return state;
  }

  RandomGroup read_random_group(const core::YamlMap& entry) {
    RandomGroup group;
    group.id = read_id(entry, "id");
    group.first_human_id = read_id(entry, "first_human_id");
    const std::vector<unsigned> size =
        entry.required<std::vector<unsigned>>("size", core::positive());
    if (size.size() != 2 || size[0] > size[1]) {
      entry.fail("size", "[min, max] member counts with 1 <= min <= max", render(size));
    }
    group.min_size = size[0];
    group.max_size = size[1];
    group.centre_min = entry.required<Eigen::Vector2d>("centre_min");
    group.centre_max = entry.required<Eigen::Vector2d>("centre_max");
    if ((group.centre_max.array() < group.centre_min.array()).any()) {
      entry.fail("centre_max", "a corner with x and y >= centre_min's", "a smaller corner");
    }
    entry.finish();
    for (model::ObjectId id = group.first_human_id; id < group.first_human_id + group.max_size;
         ++id) {
      if (!known_.humans.insert(id).second) {
        entry.fail("first_human_id",
                   "ids " + std::to_string(group.first_human_id) + ".." +
                       std::to_string(group.first_human_id + group.max_size - 1) +
                       " used by no other human",
                   "a clash on " + std::to_string(id));
      }
    }
    if (!known_.groups.insert(group.id).second) {
      entry.fail("id", "a group id used by no other group", std::to_string(group.id));
    }
    return group;
  }

  Condition read_condition(const core::YamlMap& entry) {
    const std::string type = read_type(entry, kConditionTypes);
    Condition condition;
    if (type == "distance_below" || type == "distance_above") {
      DistanceCondition c;
      c.below = type == "distance_below";
      c.from = read_agent(entry, "from");
      if (entry.has("to") == entry.has("to_point")) {
        entry.fail("to", "either an agent in `to` or a point [x, y] in `to_point` (exactly one)",
                   entry.has("to") ? "both" : "neither");
      }
      if (entry.has("to")) {
        c.to_agent = read_agent(entry, "to");
      } else {
        c.to_point = entry.required<Eigen::Vector2d>("to_point");
      }
      c.distance_m = entry.required<double>("distance", core::positive());
      condition = c;
    } else if (type == "speech_finished") {
      condition = SpeechFinishedCondition{read_agent(entry, "speaker"), read_text(entry, "act")};
    } else if (type == "goal_reached") {
      GoalReachedCondition c;
      c.who = read_agent(entry, "who");
      if (c.who.is_ari() && entry.has("tolerance")) {
        entry.fail("tolerance", "no tolerance for ARI (its navigation decides when it arrived)",
                   std::to_string(entry.required<double>("tolerance")));
      }
      c.tolerance_m = entry.optional<double>("tolerance", c.tolerance_m, core::positive());
      condition = c;
    } else if (type == "navigation_failed") {
      require_ari(entry, "type");
      condition = NavigationFailedCondition{};
    } else if (type == "time_elapsed") {
      condition = TimeElapsedCondition{entry.required<double>("seconds", core::non_negative())};
    } else if (type == "dialogue_finished") {
      condition = DialogueFinishedCondition{};
    } else if (type == "heard") {
      condition = HeardCondition{read_text(entry, "act")};
    } else if (type == "not_understood") {
      condition = NotUnderstoodCondition{};
    } else if (type == "floor_free") {
      condition = FloorFreeCondition{read_human(entry, "person")};
    } else if (type == "addressed") {
      require_ari(entry, "type");
      condition = AddressedCondition{};
    } else {
      PerceivedGroupCondition c;
      const std::vector<std::string> members = entry.required<std::vector<std::string>>("members");
      if (members.empty()) {
        entry.fail("members", "at least one agent", "an empty list");
      }
      for (const std::string& member : members) {
        const std::optional<AgentRef> ref = parse_agent_ref(member);
        if (!ref) {
          entry.fail("members", "ari or human ids", "'" + member + "'");
        }
        check_agent(*ref, entry.field_name("members"));
        c.members.push_back(*ref);
      }
      condition = c;
    }
    entry.finish();
    return condition;
  }

  Action read_action(const core::YamlMap& entry) {
    const std::string type = read_type(entry, kActionTypes);
    Action action;
    if (type == "say") {
      action = SayAction{read_agent(entry, "speaker"), read_text(entry, "act"),
                         read_text(entry, "text")};
    } else if (type == "set_goal") {
      SetGoalAction a;
      a.who = read_agent(entry, "who");
      a.goal.position = entry.required<Eigen::Vector2d>("position");
      a.goal.theta = entry.optional<double>("orientation", 0.0);
      action = a;
    } else if (type == "approach" || type == "join_group") {
      require_ari(entry, "type");
      const model::ObjectId person = read_human(entry, "person");
      action =
          type == "approach" ? Action{ApproachAction{person}} : Action{JoinGroupAction{person}};
    } else if (type == "cancel_navigation") {
      require_ari(entry, "type");
      action = CancelNavigationAction{};
    } else if (type == "add_human") {
      action = AddHumanAction{read_added_human(entry.map("human"))};
    } else if (type == "remove_human") {
      action = RemoveHumanAction{read_human(entry, "human")};
    } else if (type == "create_group") {
      action = CreateGroupAction{read_created_group(entry.map("group"))};
    } else if (type == "create_walking_group") {
      action = CreateWalkingGroupAction{read_created_walking_group(entry.map("group"))};
    } else if (type == "add_group_members") {
      AddGroupMembersAction a;
      a.group = read_group_ref(entry, "group");
      a.members = entry.required<std::vector<unsigned>>("members", core::positive());
      for (model::ObjectId id : a.members) {
        check_agent(AgentRef::human(id), entry.field_name("members"));
      }
      action = a;
    } else if (type == "converse") {
      require_ari(entry, "type");
      action = ConverseAction{};
    } else if (type == "set_group_centre") {
      action = SetGroupCentreAction{read_group_ref(entry, "group"),
                                    entry.required<Eigen::Vector2d>("centre")};
    } else if (type == "leave_group") {
      action = LeaveGroupAction{read_agent(entry, "who")};
    } else if (type == "set_posture") {
      action = SetPostureAction{read_human(entry, "who"),
                                read_named_choice(entry, "posture", world::kPostures)};
    } else if (type == "set_group_arrangement") {
      SetGroupArrangementAction a;
      a.group = read_group_ref(entry, "group");
      a.arrangement = read_named_choice(entry, "arrangement", model::kArrangements);
      if (entry.has("heading")) {
        a.heading_rad = entry.required<double>(
            "heading", core::between(-core::kMaxHeadingRad, core::kMaxHeadingRad));
      }
      action = a;
    } else {
      action =
          StopAction{entry.required<bool>("success"), entry.optional<std::string>("reason", "")};
    }
    entry.finish();
    return action;
  }

  // A human added during the run goes through the world's spawn service, which takes the
  // profile and pose only; a goal, gaze targets and a reaction follow as their own requests.
  world::HumanSpec read_added_human(const core::YamlMap& entry) {
    for (const char* key : {"motion", "words_per_minute", "reaction_params"}) {
      if (entry.has(key)) {
        entry.fail(key, "nothing: humans added during a run take the default " + std::string(key),
                   "a value");
      }
    }
    if (entry.has("gaze") && entry.map("gaze").has("directions")) {
      entry.fail("gaze", "gaze targets (humans added during a run cannot take gaze directions)",
                 "directions");
    }
    world::HumanSpec spec = world::parse_human(entry);
    if (!known_.humans.insert(spec.id).second) {
      entry.fail("id", "an id used by no other human of the scenario", std::to_string(spec.id));
    }
    if (spec.gaze) {
      // Gaze targets may be ARI, humans, walls or furniture: only humans need the later check.
      for (const world::GazeTarget& target : spec.gaze->targets) {
        if (target.id == spec.id) {
          entry.fail("gaze", "targets other than the human itself", std::to_string(target.id));
        }
        if (target.id != known_.ari_id && known_.statics.count(target.id) == 0) {
          check_agent(AgentRef::human(target.id), entry.field_name("gaze"));
        }
      }
    }
    return spec;
  }

  // A group created during the run goes through the world's service, which carries only some of
  // the spec: the rest would silently take its default live and not in process, so it is refused.
  world::GroupSpec read_created_group(const core::YamlMap& entry) {
    // Of the conversation, /sim/set_group_conversation carries the switch alone.
    if (entry.has("conversation")) {
      const core::YamlMap conversation = entry.map("conversation");
      conversation.optional<bool>("enabled", true);
      conversation.finish();
    }
    return read_created(entry,
                        {"min_ospace_radius", "member_spacing", "social_distance", "spacing_factor",
                         "step_speed", "shoulder_spacing", "facing_spread", "row_facing_spread",
                         "spacing_spread", "row_spacing_spread", "attention", "shift", "shift_turn",
                         "shift_interval", "place_gain", "turnover"},
                        "groups", world::parse_group);
  }

  // A walking group takes what /sim/create_walking_group carries.
  world::WalkingGroupSpec read_created_walking_group(const core::YamlMap& entry) {
    return read_created(entry, {"line_spacing", "wait_distance"}, "walking groups",
                        world::parse_walking_group);
  }

  // A group spec of a create action: refuses the keys its service does not carry, an id another
  // group of the scenario uses, and members that are not humans of it.
  template <class Spec>
  Spec read_created(const core::YamlMap& entry, std::initializer_list<const char*> not_carried,
                    const std::string& kind, Spec (*parse)(const core::YamlMap&)) {
    for (const char* key : not_carried) {
      if (entry.has(key)) {
        entry.fail(
            key, "nothing: " + kind + " created during a run take the default " + std::string(key),
            "a value");
      }
    }
    Spec spec = parse(entry);
    if (!known_.groups.insert(spec.id).second) {
      entry.fail("id", "a group id used by no other group of the scenario",
                 std::to_string(spec.id));
    }
    for (model::ObjectId id : spec.members) {
      check_agent(AgentRef::human(id), entry.field_name("members"));
    }
    return spec;
  }

  AgentRef read_agent(const core::YamlMap& entry, const std::string& key) {
    const AgentRef ref = read_agent_ref(entry, key);
    check_agent(ref, entry.field_name(key));
    return ref;
  }

  model::ObjectId read_human(const core::YamlMap& entry, const std::string& key) {
    const model::ObjectId id = read_human_ref(entry, key);
    check_agent(AgentRef::human(id), entry.field_name(key));
    return id;
  }

  model::ObjectId read_group_ref(const core::YamlMap& entry, const std::string& key) {
    const model::ObjectId id = read_id(entry, key);
    pending_.push_back({PendingCheck::Kind::kGroup, id, entry.field_name(key)});
    return id;
  }

  void require_ari(const core::YamlMap& entry, const std::string& key) {
    pending_.push_back({PendingCheck::Kind::kAgent, model::kNoObject, entry.field_name(key)});
  }

  void check_agent(const AgentRef& ref, const std::string& field) {
    pending_.push_back({PendingCheck::Kind::kAgent, ref.human_id, field});
  }

  // Every state name is unique, `start` and every `next` name a state.
  static void check_names(const Script& script, const core::YamlMap& map,
                          const std::vector<std::string>& next_fields) {
    std::set<std::string> names;
    for (size_t i = 0; i < script.states.size(); ++i) {
      if (!names.insert(script.states[i].name).second) {
        throw core::ConfigError(map.field_name("states[" + std::to_string(i) + "].name") +
                                ": expected a name no other state has, got '" +
                                script.states[i].name + "'");
      }
    }
    const std::string known = "the name of a state (" + join(names) + ")";
    if (names.count(script.start) == 0) {
      map.fail("start", known, "'" + script.start + "'");
    }
    size_t k = 0;
    for (const State& state : script.states) {
      for (const Transition& transition : state.transitions) {
        const std::string& field = next_fields[k++];
        if (!transition.next.empty() && names.count(transition.next) == 0) {
          throw core::ConfigError(field + ": expected " + known + ", got '" + transition.next +
                                  "'");
        }
      }
    }
  }

  // A `heard` act no human line of the script has would wait for ever.
  static void check_heard_acts(const Script& script) {
    const HeardLines lines(script);
    for (const State& state : script.states) {
      for (const Transition& transition : state.transitions) {
        for (const Condition& condition : transition.when) {
          const auto* heard = std::get_if<HeardCondition>(&condition);
          if (heard != nullptr && !lines.has_act(heard->act)) {
            throw core::ConfigError(transition.field +
                                    ".when: heard: expected the act of a line "
                                    "a human of the script says, got '" +
                                    heard->act + "'");
          }
        }
      }
    }
  }

  void check_references() const {
    for (const PendingCheck& check : pending_) {
      if (check.kind == PendingCheck::Kind::kGroup) {
        if (known_.groups.count(check.id) == 0) {
          throw core::ConfigError(
              check.field + ": expected a group of the scene or one the script creates, got " +
              std::to_string(check.id));
        }
      } else if (check.id == model::kNoObject) {
        if (!known_.has_ari) {
          throw core::ConfigError(check.field +
                                  ": expected a scene with ARI (an `ari` entry) for this line, got "
                                  "none");
        }
      } else if (known_.humans.count(check.id) == 0) {
        throw core::ConfigError(check.field +
                                ": expected a human of the scene or one the script adds, got " +
                                std::to_string(check.id));
      }
    }
  }

  static std::string join(const std::set<std::string>& names) {
    std::string text;
    for (const std::string& name : names) {
      text += (text.empty() ? "" : ", ") + name;
    }
    return text;
  }

  static std::string render(const std::vector<unsigned>& values) {
    std::ostringstream out;
    out << "[";
    for (size_t i = 0; i < values.size(); ++i) {
      out << (i == 0 ? "" : ", ") << values[i];
    }
    out << "]";
    return out.str();
  }

  KnownIds known_;
  std::vector<PendingCheck> pending_;
};

}  // namespace

Scenario parse_scenario(const core::YamlMap& root, const std::string& base_dir,
                        const std::string& name) {
  Scenario scenario;
  scenario.name = name;
  scenario.scene = world::parse_scene(root, base_dir);
  // Placing the bodies finds what the text alone cannot (overlapping spawns, unknown members).
  world::build_simulation(scenario.scene, world::SimulationConfig{});
  ScriptReader reader(scenario.scene);
  scenario.script = reader.read(root.map("script"));
  return scenario;
}

Scenario load_scenario_file(const std::string& path) {
  const std::filesystem::path file(path);
  return parse_scenario(core::YamlMap::load_file(path), file.parent_path().string(),
                        file.stem().string());
}

std::string scenario_file_of(const std::string& name_or_file, const std::string& scenario_dir) {
  if (name_or_file.find('/') == std::string::npos && name_or_file.find('.') == std::string::npos) {
    return scenario_dir + "/" + name_or_file + ".yaml";
  }
  return name_or_file;
}

}  // namespace ari_social_sim::scenario
