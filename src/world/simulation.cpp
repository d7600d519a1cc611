#include "ari_social_sim/world/simulation.hpp"

#include <box2d/b2_distance.h>
#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "ari_social_sim/core/config_check.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/number_text.hpp"
#include "ari_social_sim/core/rng_streams.hpp"
#include "ari_social_sim/world/box2d_shapes.hpp"
#include "ari_social_sim/world/request_check.hpp"

namespace ari_social_sim::world {
namespace {

// Box2D solver iterations: the manual's recommended values; agents are few and slow.
constexpr int32 kVelocityIterations = 8;
constexpr int32 kPositionIterations = 3;
// ARI's mass (kg, ari_robot's URDF: base_link 43.4 kg plus wheels and head) and a person's.
constexpr float kAriMassKg = 50.0f;
constexpr float kHumanMassKg = 70.0f;
// The id of the first group created without one.
constexpr model::ObjectId kFirstAutomaticGroupId = 1;
// About one personal distance: a neighbour query then visits a 3 x 3 block of cells.
constexpr double kAgentGridCellM = 1.0;

b2Vec2 to_b2(const Eigen::Vector2d& v) {
  return b2Vec2(static_cast<float>(v.x()), static_cast<float>(v.y()));
}

// Box2D keeps a body's user data as an integer (b2BodyUserData::pointer): ours is its Object.
Object* object_of(b2Body* body) {
  // NOLINTNEXTLINE(performance-no-int-to-ptr)
  return reinterpret_cast<Object*>(body->GetUserData().pointer);
}

template <class T>
T* find_sorted(const std::vector<std::unique_ptr<T>>& items, model::ObjectId id) {
  auto it = std::lower_bound(
      items.begin(), items.end(), id,
      [](const std::unique_ptr<T>& item, model::ObjectId key) { return item->id() < key; });
  return it != items.end() && (*it)->id() == id ? it->get() : nullptr;
}

template <class T>
void insert_sorted(std::vector<std::unique_ptr<T>>& items, std::unique_ptr<T> item) {
  auto it = std::lower_bound(
      items.begin(), items.end(), item->id(),
      [](const std::unique_ptr<T>& existing, model::ObjectId key) { return existing->id() < key; });
  items.insert(it, std::move(item));
}

// A wall or piece of furniture. Its pose is the description's (a polygon's is its centroid), not
// the body's: polygons are given in map coordinates on a body at the origin.
class StaticBody : public Object {
 public:
  explicit StaticBody(const model::StaticObject& description)
      : Object(description.id, ObjectKind::kStatic),
        is_wall_(description.type == model::ShapeType::kWall) {
    pose_ = description.pose;
  }
  void sync_from_body(double dt_s) override {}
  bool is_wall() const { return is_wall_; }

 private:
  bool is_wall_;
};

bool is_furniture(const Object& object) {
  return object.kind() == ObjectKind::kStatic && !static_cast<const StaticBody&>(object).is_wall();
}

bool is_seated(const Object& object) {
  return object.kind() == ObjectKind::kHuman &&
         static_cast<const Human&>(object).posture().seated_fraction() > 0.0;
}

b2Body* make_agent_body(b2World& physics, const core::Pose2& pose, Object& owner) {
  b2BodyDef def;
  def.type = b2_dynamicBody;
  def.position = to_b2(pose.position);
  def.angle = static_cast<float>(pose.theta);
  def.userData.pointer = reinterpret_cast<uintptr_t>(&owner);
  return physics.CreateBody(&def);
}

}  // namespace

void SimulationConfig::validate() const {
  core::check_fields(*this, "SimulationConfig");
}

Simulation::Simulation(model::WorldDescription world, SimulationConfig config)
    : world_(std::move(world)),
      config_(config),
      physics_(std::make_unique<b2World>(b2Vec2(0, 0))),
      agent_grid_(kAgentGridCellM) {
  config_.validate();
  world_.validate();
  check_map_size(world_, config_.map_resolution_m);
  for (const model::StaticObject& description : world_.objects) {
    auto object = std::make_unique<StaticBody>(description);
    b2BodyDef def;
    def.type = b2_staticBody;
    def.userData.pointer = reinterpret_cast<uintptr_t>(object.get());
    b2Body* body = physics_->CreateBody(&def);
    const StaticShape shape = make_static_shape(description);
    // Box and circle shapes are defined about the origin and placed by the body; polygons are
    // given in map coordinates and keep the identity transform.
    body->SetTransform(shape.transform.p, shape.transform.q.GetAngle());
    body->CreateFixture(&shape.shape(), 0.0f);
    object->attach_body(body);
    register_object(*object);
    statics_.push_back(std::move(object));
  }
  add_floor_fence();
}

void Simulation::add_floor_fence() {
  // The floor's edge as a fence, so that nothing leaves the world through a door (a human set
  // walking, ARI driven on) and every pose stays inside the map. It is no object: no user data.
  const Eigen::Vector2d low = world_.origin;
  const Eigen::Vector2d high = world_.origin + world_.size;
  // Clockwise: Box2D's chain edges collide on their right side only, here the floor's.
  const b2Vec2 corners[4] = {to_b2(low), to_b2({low.x(), high.y()}), to_b2(high),
                             to_b2({high.x(), low.y()})};
  b2ChainShape fence;
  fence.CreateLoop(corners, 4);
  b2BodyDef def;
  def.type = b2_staticBody;
  physics_->CreateBody(&def)->CreateFixture(&fence, 0.0f);
}

Simulation::~Simulation() = default;

void Simulation::register_object(Object& object) {
  if (!used_ids_.insert(object.id()).second) {
    throw core::RequestError("id " + std::to_string(object.id()) + " is already used" +
                             (find_object(object.id()) == nullptr ? " earlier in this run" : ""));
  }
  objects_by_id_.emplace(object.id(), &object);
}

model::ObjectId Simulation::next_free_id(model::ObjectId from) const {
  model::ObjectId id = std::max<model::ObjectId>(from, kFirstAutomaticHumanId);
  while (used_ids_.count(id) > 0) {
    ++id;
  }
  return id;
}

const Object* Simulation::find_object(model::ObjectId id) const {
  const auto it = objects_by_id_.find(id);
  return it == objects_by_id_.end() ? nullptr : it->second;
}

const Human* Simulation::find_human(model::ObjectId id) const {
  return find_sorted(humans_, id);
}

const GroupNavigation* Simulation::find_group(model::ObjectId id) const {
  return find_sorted(groups_, id);
}

Object* Simulation::mutable_object(model::ObjectId id) {
  const auto it = objects_by_id_.find(id);
  return it == objects_by_id_.end() ? nullptr : it->second;
}

Human* Simulation::mutable_human(model::ObjectId id) {
  return find_sorted(humans_, id);
}

GroupNavigation* Simulation::mutable_group(model::ObjectId id) {
  return find_sorted(groups_, id);
}

void Simulation::check_placement(const b2Shape& shape, const core::Pose2& pose,
                                 const Object* ignore, const std::string& what,
                                 bool on_a_seat) const {
  const b2Transform transform(to_b2(pose.position), b2Rot(static_cast<float>(pose.theta)));
  b2AABB box;
  shape.ComputeAABB(&box, transform, 0);
  const Eigen::Vector2d lower(box.lowerBound.x, box.lowerBound.y);
  const Eigen::Vector2d upper(box.upperBound.x, box.upperBound.y);
  if (!world_.contains(lower) || !world_.contains(upper)) {
    throw core::RequestError(what + " would stand outside the floor of world '" + world_.name +
                             "'");
  }
  struct OverlapQuery : b2QueryCallback {
    const b2Shape* shape;
    b2Transform transform;
    const Object* ignore;
    bool on_a_seat;
    const Object* hit{nullptr};
    bool ReportFixture(b2Fixture* fixture) override {
      const Object* other = object_of(fixture->GetBody());
      if (other == nullptr || other == ignore) {
        return true;  // the floor fence is checked as the floor's bounds above
      }
      if (on_a_seat && is_furniture(*other)) {
        return true;  // the world knows no seats: any furniture may be the chair
      }
      if (b2TestOverlap(shape, 0, fixture->GetShape(), 0, transform,
                        fixture->GetBody()->GetTransform())) {
        hit = other;
        return false;
      }
      return true;
    }
  } query;
  query.shape = &shape;
  query.transform = transform;
  query.ignore = ignore;
  query.on_a_seat = on_a_seat;
  physics_->QueryAABB(&query, box);
  if (query.hit != nullptr) {
    const char* kind = query.hit->kind() == ObjectKind::kStatic  ? "wall or furniture"
                       : query.hit->kind() == ObjectKind::kHuman ? "human"
                                                                 : "ARI";
    throw core::RequestError(what + " would overlap " + kind + " " +
                             std::to_string(query.hit->id()));
  }
}

const Human& Simulation::add_human(HumanSpec spec) {
  if (spec.id == model::kNoObject) {
    spec.id = next_free_id(kFirstAutomaticHumanId);
  }
  const RequestCheck check("spawn_human");
  // The service's names for the pose (its theta is the spec's orientation).
  check.on_floor("pose", spec.pose.position, world_);
  check.heading("pose.theta", spec.pose.theta);
  if (spec.goal) {
    check.on_floor("goal", spec.goal->position, world_);
  }
  check.valid(spec);
  if (find_object(spec.id) != nullptr) {
    check.fail("id", "an id no other object uses", std::to_string(spec.id));
  }
  if (used_ids_.count(spec.id) > 0) {
    check.fail("id",
               "an id not used earlier in this run (a removed human's id is not reused; "
               "/sim/reset starts over)",
               std::to_string(spec.id));
  }
  if (humans_.size() >= kMaxHumans) {
    throw core::RequestError("spawn_human: the world already holds " +
                             std::to_string(humans_.size()) + " humans, the most it may hold");
  }
  if (spec.gaze) {
    check_gaze_targets(check, spec.id, *spec.gaze);
  }
  const std::string what = "human " + std::to_string(spec.id);
  b2CircleShape circle;
  circle.m_radius = static_cast<float>(spec.motion.body_radius_m);
  check_placement(circle, spec.pose, nullptr,
                  what + " at (" + std::to_string(spec.pose.position.x()) + ", " +
                      std::to_string(spec.pose.position.y()) + ")",
                  spec.posture == Posture::kSitting);

  auto human = std::make_unique<Human>(
      spec, core::rng_for(config_.seed, core::rng_streams::kHumanGaze, spec.id),
      core::rng_for(config_.seed, core::rng_streams::kHumanReaction, spec.id));
  b2Body* body = make_agent_body(*physics_, spec.pose, *human);
  body->SetFixedRotation(true);
  // Continuous collision between people: two walkers meeting head on must not sink into each other.
  body->SetBullet(true);
  b2FixtureDef fixture;
  fixture.shape = &circle;
  fixture.density = kHumanMassKg / (b2_pi * circle.m_radius * circle.m_radius);
  fixture.friction = 0.0f;
  body->CreateFixture(&fixture);
  if (spec.posture == Posture::kSitting) {
    // As Human::apply_posture keeps it: not pushed off the seat, not pushed out of the chair.
    body->SetType(b2_kinematicBody);
  }
  human->attach_body(body);
  register_object(*human);
  agents_changed();
  Human& ref = *human;
  insert_sorted(humans_, std::move(human));
  return ref;
}

void Simulation::remove_human(model::ObjectId id) {
  Human& human = existing_human(RequestCheck("remove_human"), id);
  release_from_group(human);
  physics_->DestroyBody(human.body());
  objects_by_id_.erase(id);
  agents_changed();
  humans_.erase(std::find_if(humans_.begin(), humans_.end(),
                             [id](const std::unique_ptr<Human>& h) { return h->id() == id; }));
}

const Ari& Simulation::add_ari(const AriSpec& spec) {
  spec.validate();
  RequestCheck().on_floor("pose", spec.pose.position, world_);
  if (ari_) {
    throw core::RequestError("the world already has ARI (id " + std::to_string(ari_->id()) + ")");
  }
  if (find_object(spec.id) != nullptr) {
    throw core::RequestError("ARI: id " + std::to_string(spec.id) + " is already used");
  }
  const model::AriFootprint& f = spec.footprint;
  b2PolygonShape footprint;
  footprint.SetAsBox(static_cast<float>(0.5 * (f.front_x_m - f.rear_x_m)),
                     static_cast<float>(f.half_width_m), to_b2(f.centre_local()), 0.0f);
  check_placement(footprint, spec.pose, nullptr, "ARI");

  ari_ = std::make_unique<Ari>(spec, config_.map_resolution_m);
  b2Body* body = make_agent_body(*physics_, spec.pose, *ari_);
  body->CreateFixture(&footprint, 1.0f);
  // Mass centred on base_footprint (the wheel axle): the base turns about it like ARI does.
  b2MassData mass;
  body->GetMassData(&mass);
  mass.I *= kAriMassKg / mass.mass;  // Box2D reports I about the body origin
  mass.mass = kAriMassKg;
  mass.center.SetZero();
  body->SetMassData(&mass);
  ari_->attach_body(body);
  register_object(*ari_);
  agents_changed();
  return *ari_;
}

const GroupNavigation& Simulation::add_group(GroupSpec spec) {
  const RequestCheck check("create_group");
  spec.id = new_group_id(spec.id, check, "an id no other group uses");
  check.on_floor("centre", spec.centre, world_);
  check.valid(spec);
  check_members(check, spec.members);
  for (model::ObjectId member : spec.members) {
    Human& human = *mutable_human(member);
    leave_walking_group(human);
    if (GroupNavigation* previous = mutable_group(human.group_id())) {
      previous->remove_member(member);
    }
    human.join_group(spec.id);
  }
  drop_empty_groups();
  auto group = std::make_unique<GroupNavigation>(spec);
  GroupNavigation& ref = *group;
  insert_sorted(groups_, std::move(group));
  if (const auto old = conversations_.find(spec.id); old != conversations_.end()) {
    old->second->release(*this);  // a group of an id used before starts a conversation anew
    conversations_.erase(old);
  }
  if (spec.conversation.enabled) {
    set_group_conversation(spec.id, true);
  }
  turnovers_.erase(spec.id);
  if (spec.turnover.active()) {
    turnovers_.emplace(
        spec.id, std::make_unique<GroupTurnover>(
                     spec.turnover,
                     core::rng_for(config_.seed, core::rng_streams::kGroupTurnover, spec.id)));
  }
  return ref;
}

void Simulation::add_group_members(model::ObjectId group_id,
                                   const std::vector<model::ObjectId>& members) {
  const RequestCheck check("add_group_members");
  GroupNavigation& group = existing_group(check, group_id);
  // A longer list cannot fit, and is refused before the quadratic search for repeats below.
  if (members.size() > kMaxGroupMembers) {
    check.fail("members", "at most " + std::to_string(kMaxGroupMembers) + " humans",
               std::to_string(members.size()));
  }
  check_members(check, members);
  size_t joining = 0;
  for (size_t i = 0; i < members.size(); ++i) {
    const auto before = members.begin() + static_cast<std::ptrdiff_t>(i);
    const bool repeated = std::find(members.begin(), before, members[i]) != before;
    joining += find_human(members[i])->group_id() != group_id && !repeated ? 1 : 0;
  }
  if (group.members().size() + joining > kMaxGroupMembers) {
    check.fail("members", "at most " + std::to_string(kMaxGroupMembers) + " humans in a group",
               std::to_string(group.members().size()) + " members and " + std::to_string(joining) +
                   " joining");
  }
  for (model::ObjectId member : members) {
    Human& human = *mutable_human(member);
    if (human.group_id() == group_id) {
      continue;
    }
    leave_walking_group(human);
    if (GroupNavigation* previous = mutable_group(human.group_id())) {
      previous->remove_member(member);
    }
    human.join_group(group_id);
    group.add_member(member);
  }
  drop_empty_groups();
}

void Simulation::check_members(const RequestCheck& check,
                               const std::vector<model::ObjectId>& members) const {
  for (size_t i = 0; i < members.size(); ++i) {
    if (find_human(members[i]) == nullptr) {
      check.unknown_id("members[" + std::to_string(i) + "]", "human", members[i]);
    }
  }
}

void Simulation::drop_empty_groups() {
  groups_.erase(std::remove_if(
                    groups_.begin(), groups_.end(),
                    [](const std::unique_ptr<GroupNavigation>& g) { return g->members().empty(); }),
                groups_.end());
  walking_groups_.erase(
      std::remove_if(walking_groups_.begin(), walking_groups_.end(),
                     [](const std::unique_ptr<WalkingGroup>& g) { return g->members().empty(); }),
      walking_groups_.end());
}

model::ObjectId Simulation::new_group_id(model::ObjectId requested, const RequestCheck& check,
                                         const std::string& expected) const {
  if (requested != model::kNoObject) {
    if (find_group(requested) != nullptr || find_walking_group(requested) != nullptr) {
      check.fail("id", expected, std::to_string(requested));
    }
    return requested;
  }
  model::ObjectId highest = kFirstAutomaticGroupId - 1;
  if (!groups_.empty()) {
    highest = std::max(highest, groups_.back()->id());
  }
  if (!walking_groups_.empty()) {
    highest = std::max(highest, walking_groups_.back()->id());
  }
  return highest + 1;
}

const WalkingGroup* Simulation::find_walking_group(model::ObjectId id) const {
  return find_sorted(walking_groups_, id);
}

WalkingGroup* Simulation::mutable_walking_group(model::ObjectId id) {
  return find_sorted(walking_groups_, id);
}

const WalkingGroup& Simulation::add_walking_group(WalkingGroupSpec spec) {
  const RequestCheck check("create_walking_group");
  spec.id = new_group_id(spec.id, check, "an id no other group (walking or conversing) uses");
  check.pose_on_floor("goal", spec.goal, world_);
  check.valid(spec);
  check_members(check, spec.members);
  // Members keep their own max_speed: a group faster than its slowest member would leave it
  // behind and wait for it for ever.
  double slowest = std::numeric_limits<double>::infinity();
  double widest = 0.0;
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
  std::vector<Eigen::Vector2d> positions;
  for (model::ObjectId member : spec.members) {
    const Human& human = *find_human(member);
    slowest = std::min(slowest, human.spec().motion.max_speed_mps);
    widest = std::max(widest, human.spec().motion.body_radius_m);
    positions.push_back(human.pose().position);
    centroid += human.pose().position;
  }
  centroid /= static_cast<double>(spec.members.size());
  if (spec.speed_mps > slowest) {
    check.fail("speed",
               "at most the slowest member's max_speed (" + core::number_text(slowest) + " m/s)",
               core::number_text(spec.speed_mps));
  }
  // A conversation on arrival must be a group the world accepts.
  if (spec.on_arrival == ArrivalAction::kConverse) {
    GroupSpec conversation;
    conversation.id = spec.id;
    conversation.members = spec.members;
    conversation.centre = spec.goal.position;
    conversation.arrangement = spec.arrangement;
    check.valid(conversation);
  }
  std::optional<WalkingRoute> route =
      WalkingRoute::plan(world_, centroid, spec.goal.position, widest + kWalkingWallMarginM);
  if (!route) {
    check.fail("goal",
               "a goal the members can walk to from their centroid (" +
                   core::number_text(centroid.x()) + ", " + core::number_text(centroid.y()) +
                   ") keeping " + core::number_text(widest + kWalkingWallMarginM) +
                   " m from walls and furniture",
               "(" + core::number_text(spec.goal.position.x()) + ", " +
                   core::number_text(spec.goal.position.y()) + ")");
  }
  for (model::ObjectId member : spec.members) {
    Human& human = *mutable_human(member);
    release_from_group(human);
    human.join_group(spec.id);
  }
  auto group = std::make_unique<WalkingGroup>(spec, std::move(*route), widest, positions);
  WalkingGroup& ref = *group;
  insert_sorted(walking_groups_, std::move(group));
  return ref;
}

void Simulation::leave_walking_group(Human& human) {
  if (WalkingGroup* walking = mutable_walking_group(human.group_id())) {
    walking->remove_member(human.id());
    human.leave_group();
    drop_empty_groups();
  }
}

void Simulation::converse_on_arrival() {
  std::vector<GroupSpec> conversations;
  for (const std::unique_ptr<WalkingGroup>& walking : walking_groups_) {
    if (walking->has_arrived() && walking->spec().on_arrival == ArrivalAction::kConverse) {
      conversations.push_back(walking->conversation());
    }
  }
  for (const GroupSpec& conversation : conversations) {
    // Checked when the walking group was created, and its id is kept for it: add_group cannot
    // refuse it once the walking group is gone.
    for (model::ObjectId member : conversation.members) {
      leave_walking_group(*mutable_human(member));
    }
    add_group(conversation);
  }
}

void Simulation::set_human_goal(model::ObjectId human_id, const core::Pose2& goal) {
  const RequestCheck check("set_goal");
  Human& human = existing_human(check, human_id);
  check.pose_on_floor("goal", goal, world_);
  release_from_group(human);
  human.set_goal(goal);
}

void Simulation::set_human_velocity(model::ObjectId human_id, const Eigen::Vector2d& velocity_mps,
                                    double angular_velocity_rps) {
  const RequestCheck check("set_velocity");
  Human& human = existing_human(check, human_id);
  check.finite("vx", velocity_mps.x());
  check.finite("vy", velocity_mps.y());
  // hypot: the norm of (1e300, 0) must not overflow to infinity on the way.
  const double speed = std::hypot(velocity_mps.x(), velocity_mps.y());
  const double max_speed = human.spec().motion.max_speed_mps;
  if (!(speed <= max_speed)) {
    check.fail("(vx, vy)",
               "a speed of at most " + core::number_text(max_speed) + " m/s (human " +
                   std::to_string(human_id) + "'s max_speed)",
               core::number_text(speed) + " m/s");
  }
  check.in_range("omega", angular_velocity_rps,
                 core::between(-kMaxHumanTurnRateRps, kMaxHumanTurnRateRps), "rad/s");
  release_from_group(human);
  human.set_velocity(velocity_mps, angular_velocity_rps);
}

void Simulation::set_human_reaction(model::ObjectId human_id, const std::string& profile) {
  const RequestCheck check("set_reaction");
  existing_human(check, human_id);
  for (const auto& choice : kReactionProfiles) {
    if (profile == choice.name) {
      set_human_reaction(human_id, choice.value);
      return;
    }
  }
  check.fail("profile", core::choice_names(kReactionProfiles), "'" + profile + "'");
}

void Simulation::set_human_reaction(model::ObjectId human_id, ReactionProfile profile) {
  Human& human = existing_human(RequestCheck("set_reaction"), human_id);
  human.set_reaction(profile);
}

void Simulation::set_human_posture(model::ObjectId human_id, Posture posture) {
  Human& human = existing_human(RequestCheck("set_posture"), human_id);
  if (posture == Posture::kSitting && human.motion_mode() != MotionMode::kGroup) {
    human.stop();
  }
  human.change_posture(posture);
}

void Simulation::set_human_gaze(model::ObjectId human_id, const GazeModel& model) {
  const RequestCheck check("set_gaze_targets");
  Human& human = existing_human(check, human_id);
  check.valid(model);
  check_gaze_targets(check, human_id, model);
  human.set_gaze_model(model);
}

void Simulation::check_gaze_targets(const RequestCheck& check, model::ObjectId human_id,
                                    const GazeModel& model) const {
  for (size_t i = 0; i < model.targets.size(); ++i) {
    const model::ObjectId target = model.targets[i].id;
    if (find_object(target) == nullptr || target == human_id) {
      check.fail("targets[" + std::to_string(i) + "]", "another object of the world",
                 std::to_string(target));
    }
  }
}

void Simulation::set_group_centre(model::ObjectId group_id, const Eigen::Vector2d& centre) {
  const RequestCheck check("set_group_centre");
  GroupNavigation& group = existing_group(check, group_id);
  check.on_floor("centre", centre, world_);
  group.set_centre(centre);
}

void Simulation::set_group_arrangement(model::ObjectId group_id, model::Arrangement arrangement,
                                       std::optional<double> heading_rad) {
  const RequestCheck check("set_group_arrangement");
  GroupNavigation& group = existing_group(check, group_id);
  if (heading_rad) {
    check.heading("heading", *heading_rad);
  }
  group.set_arrangement(arrangement, heading_rad);
}

void Simulation::join_group(model::ObjectId group_id, model::ObjectId agent_id) {
  const RequestCheck check("join_group");
  GroupNavigation& group = existing_group(check, group_id);
  Object& agent = existing_agent(check, "agent_id", agent_id);
  if (agent.kind() == ObjectKind::kHuman) {
    add_group_members(group_id, {agent_id});
    return;
  }
  // ARI takes part in one formation at a time.
  for (const std::unique_ptr<GroupNavigation>& other : groups_) {
    if (other.get() != &group && other->robot_joining() == agent_id) {
      other->robot_leave();
    }
  }
  group.robot_join(agent_id);
}

void Simulation::leave_group(model::ObjectId agent_id) {
  const RequestCheck check("leave_group");
  Object& agent = existing_agent(check, "agent_id", agent_id);
  if (agent.kind() == ObjectKind::kAri) {
    bool joined = false;
    for (const std::unique_ptr<GroupNavigation>& group : groups_) {
      if (group->robot_joining() == agent_id) {
        group->robot_leave();
        joined = true;
      }
    }
    if (!joined) {
      check.fail("agent_id", "an agent in a group", "ARI, who is in none");
    }
    return;
  }
  Human& human = static_cast<Human&>(agent);
  // A walker stops where it is; the others walk on.
  if (find_walking_group(human.group_id()) != nullptr) {
    leave_walking_group(human);
    return;
  }
  const GroupNavigation* group = find_group(human.group_id());
  if (group == nullptr) {
    check.fail("agent_id", "an agent in a group",
               "human " + std::to_string(agent_id) + ", who is in none");
  }
  const Eigen::Vector2d from_centre = human.pose().position - group->centre();
  const Eigen::Vector2d outward = from_centre.squaredNorm() > 1e-12
                                      ? Eigen::Vector2d(from_centre.normalized())
                                      : Eigen::Vector2d(-human.pose().heading());
  const core::Pose2 step_out{human.pose().position + kLeaveStepM * outward,
                             std::atan2(outward.y(), outward.x())};
  release_from_group(human);
  // Out of the formation where there is room; a member hemmed in by a wall stays and turns.
  bool room = world_.contains(step_out.position);
  if (room) {
    try {
      check_placement(*human.body()->GetFixtureList()->GetShape(), step_out, &human, "");
    } catch (const core::RequestError&) {
      room = false;
    }
  }
  if (room) {
    human.set_goal(step_out);
  } else {
    human.stop();
  }
}

Human& Simulation::existing_human(const RequestCheck& check, model::ObjectId human_id) {
  Human* human = mutable_human(human_id);
  if (human == nullptr) {
    check.unknown_id("id", "human", human_id);
  }
  return *human;
}

GroupNavigation& Simulation::existing_group(const RequestCheck& check, model::ObjectId group_id) {
  GroupNavigation* group = mutable_group(group_id);
  if (group == nullptr) {
    check.unknown_id("group_id", "group", group_id);
  }
  return *group;
}

Object& Simulation::existing_agent(const RequestCheck& check, const std::string& field,
                                   model::ObjectId id) {
  Object* object = mutable_object(id);
  if (object == nullptr || object->kind() == ObjectKind::kStatic) {
    check.unknown_id(field, "human or ARI", id);
  }
  return *object;
}

double Simulation::say(model::ObjectId speaker_id, const std::string& act,
                       const std::string& content) {
  existing_agent(RequestCheck("say"), "speaker_id", speaker_id);
  SpeechGenerator& speech = *mutable_speech(speaker_id);
  speech.say(act, content, time_s());
  return speech.duration_s(content);
}

SpeechGenerator* Simulation::mutable_speech(model::ObjectId id) {
  if (ari_ && ari_->id() == id) {
    return &ari_->speech();
  }
  Human* human = mutable_human(id);
  return human != nullptr ? &human->speech() : nullptr;
}

void Simulation::set_group_conversation(model::ObjectId group_id, bool enabled) {
  const GroupNavigation& group = existing_group(RequestCheck("set_group_conversation"), group_id);
  const auto it = conversations_.find(group_id);
  if (!enabled && it != conversations_.end()) {
    it->second->release(*this);
    conversations_.erase(it);
  } else if (enabled && it == conversations_.end()) {
    conversations_.emplace(
        group_id, std::make_unique<GroupConversation>(
                      group_id, group.spec().conversation,
                      core::rng_for(config_.seed, core::rng_streams::kGroupConversation, group_id),
                      core::rng_for(config_.seed, core::rng_streams::kGroupNods, group_id)));
  }
}

void Simulation::set_conversation_lines(std::shared_ptr<const ConversationLines> lines) {
  conversation_lines_ = std::move(lines);
}

const GroupConversation* Simulation::find_conversation(model::ObjectId group_id) const {
  const auto it = conversations_.find(group_id);
  return it == conversations_.end() ? nullptr : it->second.get();
}

// A group's part (its conversation, its turnover) is stepped while the group exists; the part of
// a group that ended is handed to `drop` and forgotten.
template <class Part, class StepPart, class DropPart>
void Simulation::step_parts_of_groups(std::map<model::ObjectId, std::unique_ptr<Part>>& parts,
                                      StepPart step, DropPart drop) {
  for (auto it = parts.begin(); it != parts.end();) {
    const GroupNavigation* group = find_group(it->first);
    if (group == nullptr) {
      drop(*it->second);
      it = parts.erase(it);
      continue;
    }
    step(*it->second, *group);
    ++it;
  }
}

void Simulation::step_conversations(const StepContext& context) {
  step_parts_of_groups(
      conversations_,
      [&](GroupConversation& conversation, const GroupNavigation& group) {
        conversation.step(context, group, conversation_lines_.get());
      },
      [&](GroupConversation& conversation) { conversation.release(*this); });
}

// After the conversations: a member leaves or a passer-by joins between two turns' steps. Groups
// are looked up afresh, as a departure may end one.
void Simulation::step_turnovers() {
  step_parts_of_groups(
      turnovers_,
      [&](GroupTurnover& turnover, const GroupNavigation& group) {
        turnover.step(*this, group, config_.step_s);
      },
      [](GroupTurnover&) {});
}

void Simulation::release_from_group(Human& human) {
  leave_walking_group(human);
  if (GroupNavigation* group = mutable_group(human.group_id())) {
    group->remove_member(human.id());
    human.leave_group();
    drop_empty_groups();
  }
}

void Simulation::set_pose(model::ObjectId id, const core::Pose2& pose) {
  const RequestCheck check("set_pose");
  Object* object = &existing_agent(check, "id", id);
  check.pose_on_floor("pose", pose, world_);
  b2Body* body = object->body();
  check_placement(*body->GetFixtureList()->GetShape(), pose, object, "object " + std::to_string(id),
                  is_seated(*object));
  if (object->kind() == ObjectKind::kHuman) {
    release_from_group(static_cast<Human&>(*object));
  }
  body->SetTransform(to_b2(pose.position), static_cast<float>(pose.theta));
  body->SetLinearVelocity(b2Vec2(0, 0));
  object->sync_from_body(config_.step_s);
  agents_changed();
  if (object->kind() == ObjectKind::kHuman) {
    static_cast<Human*>(object)->set_orientation(pose.theta);
  }
}

void Simulation::command_ari_twist(double linear_mps, double angular_rps) {
  if (!ari_) {
    throw core::RequestError("the world has no ARI");
  }
  const RequestCheck check("cmd_vel");
  check.finite("linear.x", linear_mps);
  check.finite("angular.z", angular_rps);
  diagnostics_.clamped_commands += ari_->drive().command(linear_mps, angular_rps, time_s());
}

void Simulation::follow_ari(const core::Pose2& pose, double linear_mps, double angular_rps) {
  if (!ari_) {
    throw core::RequestError("the world has no ARI to follow");
  }
  const RequestCheck check("follow_ari");
  check.finite("pose.x", pose.position.x());
  check.finite("pose.y", pose.position.y());
  check.heading("pose.theta", pose.theta);
  check.finite("linear", linear_mps);
  check.finite("angular", angular_rps);
  ari_->follow(pose, linear_mps, angular_rps);
}

void Simulation::command_ari_head_pan(double pan_rad) {
  if (!ari_) {
    throw core::RequestError("the world has no ARI");
  }
  RequestCheck("head_command").finite("position", pan_rad);
  diagnostics_.clamped_commands += ari_->head().command_position(pan_rad);
}

void Simulation::command_ari_head_pan_velocity(double pan_velocity_rps) {
  if (!ari_) {
    throw core::RequestError("the world has no ARI");
  }
  RequestCheck("head_command").finite("velocity", pan_velocity_rps);
  diagnostics_.clamped_commands += ari_->head().command_velocity(pan_velocity_rps);
}

void Simulation::agent_centres_near(const Eigen::Vector2d& point, double radius_m,
                                    const Object* exclude, std::vector<Eigen::Vector2d>& out,
                                    model::ObjectId exclude_group) const {
  if (agent_grid_stale_) {
    std::vector<const Object*> agents;
    agents.reserve(humans_.size() + 1);
    for (const std::unique_ptr<Human>& human : humans_) {
      agents.push_back(human.get());
    }
    if (ari_) {
      agents.push_back(ari_.get());
    }
    agent_grid_.rebuild(agents);
    agent_grid_stale_ = false;
  }
  out.clear();
  const double radius_sq = radius_m * radius_m;
  agent_grid_.for_each_near(
      point, radius_m, [&](const Object& other, const Eigen::Vector2d& centre) {
        if (&other == exclude || (centre - point).squaredNorm() >= radius_sq) {
          return;
        }
        if (exclude_group != model::kNoObject && other.kind() == ObjectKind::kHuman &&
            static_cast<const Human&>(other).group_id() == exclude_group) {
          return;
        }
        out.push_back(centre);
      });
}

double Simulation::static_penetration_m(const Object& agent) const {
  double deepest = -std::numeric_limits<double>::infinity();
  const b2Fixture* own = agent.body()->GetFixtureList();
  for (const std::unique_ptr<Object>& object : statics_) {
    const b2Fixture* fixture = object->body()->GetFixtureList();
    b2DistanceInput input;
    input.proxyA.Set(own->GetShape(), 0);
    input.proxyB.Set(fixture->GetShape(), 0);
    input.transformA = agent.body()->GetTransform();
    input.transformB = object->body()->GetTransform();
    // Distance between the cores; the agent's radius (circle) counts as its extent.
    input.useRadii = false;
    b2SimplexCache cache;
    cache.count = 0;
    b2DistanceOutput output;
    b2Distance(&output, &cache, &input);
    const double extent =
        own->GetShape()->GetType() == b2Shape::e_circle ? own->GetShape()->m_radius : 0.0;
    deepest = std::max(deepest, extent - static_cast<double>(output.distance));
  }
  return deepest;
}

double Simulation::static_clearance_m(const Eigen::Vector2d& point, double radius_m) const {
  // The floor's edge first: the fence is no object, and beyond it nobody can stand.
  const Eigen::Vector2d low = world_.origin;
  const Eigen::Vector2d high = world_.origin + world_.size;
  double clearance = std::min({point.x() - low.x(), high.x() - point.x(), point.y() - low.y(),
                               high.y() - point.y()}) -
                     radius_m;
  b2CircleShape probe;
  probe.m_radius = 0.0f;  // a point: the radius is subtracted below, in double
  b2Transform at;
  at.Set(to_b2(point), 0.0f);
  for (const std::unique_ptr<Object>& object : statics_) {
    const b2Fixture* fixture = object->body()->GetFixtureList();
    b2DistanceInput input;
    input.proxyA.Set(&probe, 0);
    input.proxyB.Set(fixture->GetShape(), 0);
    input.transformA = at;
    input.transformB = object->body()->GetTransform();
    input.useRadii = true;  // the obstacles' own skin counts as part of them
    b2SimplexCache cache;
    cache.count = 0;
    b2DistanceOutput output;
    b2Distance(&output, &cache, &input);
    clearance = std::min(clearance, static_cast<double>(output.distance) - radius_m);
  }
  return clearance;
}

void Simulation::step() {
  const StepContext context{*this, time_s(), config_.step_s};

  // 1. Objects and their generator components, then the motion they planned.
  for (const std::unique_ptr<Human>& human : humans_) {
    human->step_components(ComponentPhase::kGenerator, context);
  }
  if (ari_) {
    ari_->step_components(ComponentPhase::kGenerator, context);
  }
  for (const std::unique_ptr<Human>& human : humans_) {
    human->apply_motion(context);
  }
  if (ari_) {
    ari_->apply_motion(context);
  }

  // 2. Physics: positions, collisions with walls, furniture and each other.
  physics_->Step(static_cast<float>(config_.step_s), kVelocityIterations, kPositionIterations);
  for (const std::unique_ptr<Human>& human : humans_) {
    human->sync_from_body(config_.step_s);
  }
  if (ari_) {
    ari_->sync_from_body(config_.step_s);
  }
  agents_changed();

  // 3. Sensor components.
  for (const std::unique_ptr<Human>& human : humans_) {
    human->step_components(ComponentPhase::kSensor, context);
  }
  if (ari_) {
    ari_->step_components(ComponentPhase::kSensor, context);
  }

  // 4. Scripts.
  for (const std::unique_ptr<GroupNavigation>& group : groups_) {
    group->step(context);
  }
  for (const std::unique_ptr<WalkingGroup>& walking : walking_groups_) {
    walking->step(context);
  }
  step_conversations(context);
  step_turnovers();
  converse_on_arrival();
  ++step_count_;
}

}  // namespace ari_social_sim::world
