#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <map>
#include <optional>
#include <vector>

#include "ari_social_sim/core/pose2.hpp"
#include "ari_social_sim/physics/person_shape.hpp"
#include "ari_social_sim/rendering/human_figure.hpp"
#include "ari_social_sim/rendering/renderer.hpp"
#include "ari_social_sim/rendering/weight_shifts.hpp"
#include "ari_social_sim/world/world_snapshot.hpp"

namespace ari_social_sim::rendering {

/// A person as the cameras need them at one instant.
struct FigureInput {
  HumanTraits traits;
  core::Pose2 pose;                                       // map frame
  Eigen::Vector2d velocity_mps{Eigen::Vector2d::Zero()};  // map frame: drives the gait
  double face_yaw_rad{0.0};                               // gaze direction, map frame
  double head_pitch_rad{0.0};                             // positive: down (a nod)
  bool speaking{false};
  double seated{0.0};    // 0 standing, 1 seated (world::PostureState::seated_fraction)
  double walked_m{0.0};  // on foot so far (world::HumanSnapshot::walked_m): the gait's phase
};

FigureInput figure_input_of(const world::HumanSnapshot& human);
FigureInput figure_input_of(const physics::PersonState& person);

/// One person posed in the last update, and where they are in the mesh and label images.
struct PosedPerson {
  uint32_t id{0};
  const HumanFigure* figure{nullptr};
  FigurePose pose;
  VertexRange vertices;  // their triangles in mesh()
  uint16_t body_label{0};
  uint16_t face_label{0};
};

/// Everyone's figure, built once per person (again only when their traits change) and posed each
/// frame: the dynamic part of the cameras' scene. A person's gait phase follows the distance they
/// have walked (FigureInput::walked_m), so that whoever poses them from the same world state
/// poses them alike; they shift their weight while they stand.
class PeopleFigures {
 public:
  /// `appearance_seed` with each person's id draws their look (appearance_of) and when they
  /// shift their weight (WeightShifts).
  explicit PeopleFigures(uint64_t appearance_seed = 0);

  /// Poses everyone present at sim time `time_s`; people absent from `people` are forgotten.
  void update(double time_s, const std::vector<FigureInput>& people);

  /// All posed figures, person after person, labelled (body_label, face_label) each.
  const RenderMesh& mesh() const { return mesh_; }
  const std::vector<PosedPerson>& posed() const { return posed_; }

  /// The person (index into posed()) a label image value belongs to, and whether it is their
  /// face; nullopt for 0 (no person) and for labels of others.
  struct LabelOwner {
    size_t person;
    bool face;
  };
  std::optional<LabelOwner> owner_of(uint16_t label) const;

 private:
  struct Person {
    HumanTraits traits;
    HumanFigure figure;
    double last_time_s{0.0};
    double gesture{0.0};  // FigurePose::gesture, following whether they speak
    WeightShifts weight_shifts;
  };

  uint64_t appearance_seed_;
  std::map<uint32_t, Person> people_;
  RenderMesh mesh_;
  std::vector<PosedPerson> posed_;
};

}  // namespace ari_social_sim::rendering
