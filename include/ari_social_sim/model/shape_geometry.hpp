#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "ari_social_sim/model/world_description.hpp"

namespace ari_social_sim::model {

// What Box2D 2.4 accepts as a shape, checked before anything reaches it: a polygon it cannot
// build stops the process with an assertion (SIGABRT, no message). b2PolygonShape::Set welds
// vertices closer than b2_linearSlop / 2 and asserts when fewer than three remain, asserts that
// every hull edge is longer than b2_epsilon, and its centroid asserts an area above b2_epsilon
// (FLT_EPSILON, about 1.2e-7 m^2); a dynamic body's mass asserts the same area. The limits below
// keep every shape well clear of those, at Box2D's own length scale (world/box2d_shapes.cpp
// checks that they match the installed Box2D).

/// Box2D's b2_linearSlop (m): its collision tolerance, the smallest feature it resolves. Every
/// edge, every polygon's width, every box side and circle radius must be at least this long.
constexpr double kMinShapeFeatureM = 0.005;
/// Vertices closer than this (m) are one point to Box2D (b2PolygonShape::Set welds them).
constexpr double kBox2dWeldDistanceM = 0.5 * kMinShapeFeatureM;
/// Smallest polygon area (m^2): a square of kMinShapeFeatureM sides, 200 times Box2D's limit.
constexpr double kMinPolygonAreaM2 = kMinShapeFeatureM * kMinShapeFeatureM;
/// Box2D takes convex polygons of at most 8 vertices (b2_maxPolygonVertices).
constexpr size_t kMinPolygonVertices = 3;
constexpr size_t kMaxPolygonVertices = 8;

/// What a polygon must be, as error messages state it.
std::string polygon_expectation();

/// "" if Box2D can take `points` as a polygon, else what is wrong with them, by name and with
/// numbers, checked in this order: the vertex count, "non-finite" coordinates, "tiny" (area below
/// kMinPolygonAreaM2), "duplicate vertices" (closer than kBox2dWeldDistanceM), "sliver" (thinner
/// than kMinShapeFeatureM across, with its aspect ratio), "short edge", "collinear" (a vertex
/// within kMinShapeFeatureM of the line through its neighbours), "not convex".
std::string polygon_defect(const std::vector<Eigen::Vector2d>& points);

/// True if the vertices form a strictly convex polygon, in either winding.
bool is_convex(const std::vector<Eigen::Vector2d>& points);

/// "" if Box2D can take the object's shape (a polygon per polygon_defect; a box or wall with both
/// sides, a circle with a radius, of at least kMinShapeFeatureM; finite pose), else what is wrong.
std::string static_object_defect(const StaticObject& object);

}  // namespace ari_social_sim::model
