// triangle and smooth_triangle: three corners (and, smooth, a normal at each).
#pragma once

#include "trace/pov_bounds.h"
#include "trace/shapes/common.h"

namespace povwall::trace {

struct OracleRay;
struct OracleBest;

void intersect_triangle(const Point3 p[3], const Point3& o, const Vector3& dir,
                        Crossings& out, Real min_t = kTriangleTolerance);
// POV-Ray's degenerate triangle: its normal (P1 - P2) x (P3 - P2) has length exactly 0
// (Triangle::Compute_Triangle, 3.7:source/backend/shape/triangle.cpp:314). It has no
// normal, so it is never hit; a tiny triangle (edges of 1e-6) still is.
inline bool degenerate_triangle(const Point3 p[3]) {
    return length(cross(p[0] - p[1], p[2] - p[1])) == 0;
}
// A flat triangle's normal with POV-Ray's sign, (p0 - p1) x (p2 - p1) (Triangle and mesh
// triangles alike; unnormalised).
inline Vector3 pov_triangle_normal(const Point3 (&p)[3]) {
    return cross(p[0] - p[1], p[2] - p[1]);
}
// The vertex normals `n` interpolated at p (unnormalised).
Vector3 smooth_triangle_normal(const Point3 (&corner)[3], const Vector3* n,
                               const Point3& p);

void shape_hits(const Triangle& t, const LocalRay& r, ShapeHits& out);
Vector3 shape_normal(const Triangle& t, const ShapeHit& h);
bool shape_inside(const Triangle& t, const Point3& p);
Bounds3 shape_bounds(const Triangle& t);
PovBBox shape_pov_bbox(const Triangle& t, const CompactTransform& xf);
constexpr bool shape_pov_tests_own_bbox(const Triangle&) { return false; }
constexpr bool shape_convex(const Triangle&) { return true; }
constexpr bool shape_invertible(const Triangle&) { return false; }
constexpr bool shape_has_no_inside(const Triangle&) { return true; }
bool shape_oracle_first(const Triangle& t, const OracleRay& r, OracleBest& best);

void shape_hits(const SmoothTriangle& t, const LocalRay& r, ShapeHits& out);
Vector3 shape_normal(const SmoothTriangle& t, const ShapeHit& h);
bool shape_inside(const SmoothTriangle& t, const Point3& p);
Bounds3 shape_bounds(const SmoothTriangle& t);
PovBBox shape_pov_bbox(const SmoothTriangle& t, const CompactTransform& xf);
constexpr bool shape_pov_tests_own_bbox(const SmoothTriangle&) { return false; }
// Its shading normals bend: a lit point can face away from the light.
constexpr bool shape_convex(const SmoothTriangle&) { return false; }
constexpr bool shape_invertible(const SmoothTriangle&) { return false; }
constexpr bool shape_has_no_inside(const SmoothTriangle&) { return true; }
bool shape_oracle_first(const SmoothTriangle& t, const OracleRay& r, OracleBest& best);

}  // namespace povwall::trace
