// sphere: centre and radius (POV-Ray's Sphere; an unevenly scaled one is its ellipsoid).
#pragma once

#include "trace/pov_bounds.h"
#include "trace/shapes/common.h"

namespace povwall::trace {

struct OracleRay;
struct OracleBest;

// `dir` must be unit length. Crossings with t > kSphereTolerance; a tangent ray (half
// chord not above EPSILON) misses.
void intersect_sphere(const Sphere& s, const Point3& o, const Vector3& dir,
                      Crossings& out);
Vector3 sphere_normal(const Sphere& s, const Point3& p);
bool inside_sphere(const Sphere& s, const Point3& p);

void shape_hits(const Sphere& s, const LocalRay& r, ShapeHits& out);
Vector3 shape_normal(const Sphere& s, const ShapeHit& h);
bool shape_inside(const Sphere& s, const Point3& p);
bool shape_inside_inverted(const Sphere& s, const Point3& p);
Bounds3 shape_bounds(const Sphere& s);
PovBBox shape_pov_bbox(const Sphere& s, const CompactTransform& xf);
constexpr bool shape_pov_tests_own_bbox(const Sphere&) { return false; }
constexpr bool shape_convex(const Sphere&) { return true; }
constexpr bool shape_invertible(const Sphere&) { return true; }
bool shape_oracle_first(const Sphere& s, const OracleRay& r, OracleBest& best);

}  // namespace povwall::trace
