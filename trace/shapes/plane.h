// plane: dot(normal, p) = distance; inside is the side the normal points away from.
#pragma once

#include "trace/pov_bounds.h"
#include "trace/shapes/common.h"

namespace povwall::trace {

struct OracleRay;
struct OracleBest;

void intersect_plane(const Plane& p, const Point3& o, const Vector3& dir, Crossings& out,
                     Real min_t = kPlaneTolerance);
bool inside_plane(const Plane& pl, const Point3& p);

void shape_hits(const Plane& p, const LocalRay& r, ShapeHits& out);
Vector3 shape_normal(const Plane& p, const ShapeHit& h);
bool shape_inside(const Plane& p, const Point3& q);
bool shape_inside_inverted(const Plane& p, const Point3& q);
Bounds3 shape_bounds(const Plane& p);  // everything
PovBBox shape_pov_bbox(const Plane& p, const CompactTransform& xf);
constexpr bool shape_pov_tests_own_bbox(const Plane&) { return false; }
constexpr bool shape_convex(const Plane&) { return true; }
constexpr bool shape_invertible(const Plane&) { return true; }
bool shape_oracle_first(const Plane& p, const OracleRay& r, OracleBest& best);

}  // namespace povwall::trace
