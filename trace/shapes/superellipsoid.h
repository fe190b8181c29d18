// superellipsoid: POV-Ray's sampled root search of its implicit function along the ray
// (no polynomial): 9 planes through the origin cut the ray inside the box [-1.01, 1.01]^3
// into pieces on which the function is unimodal; a sign change is refined by secant and
// bisection, a piece without one is probed for a touching surface.
#pragma once

#include "trace/pov_bounds.h"
#include "trace/shapes/common.h"

namespace povwall::trace {

struct OracleRay;
struct OracleBest;

// POV-Ray's implicit function: (|x|^a + |y|^a)^(1/a) raised to b, plus |z|^b, to the
// power 1/b, minus 1, with a = 2/e and b = 2/n. Negative inside, zero on the surface.
Real superellipsoid_value(const Superellipsoid& s, const Point3& p);
// The crossings along a unit direction from `o`, nearest first (object distances), whose
// world distance (object distance / `dir_length`) lies in (1e-4, 1e7).
void intersect_superellipsoid(const Superellipsoid& s, const Point3& o,
                              const Vector3& dir, Real dir_length, ShapeHits& out);
Vector3 superellipsoid_normal(const Superellipsoid& s, const Point3& p);

void shape_hits(const Superellipsoid& s, const LocalRay& r, ShapeHits& out);
Vector3 shape_normal(const Superellipsoid& s, const ShapeHit& h);
bool shape_inside(const Superellipsoid& s, const Point3& p);
Bounds3 shape_bounds(const Superellipsoid& s);
PovBBox shape_pov_bbox(const Superellipsoid& s, const CompactTransform& xf);
constexpr bool shape_pov_tests_own_bbox(const Superellipsoid&) { return true; }
// Convex for e, n <= 2, but its sampled hits are not exact: a lit point may find its own
// surface again, as POV-Ray does, so it is never treated as convex.
constexpr bool shape_convex(const Superellipsoid&) { return false; }
constexpr bool shape_invertible(const Superellipsoid&) { return true; }
bool shape_oracle_first(const Superellipsoid& s, const OracleRay& r, OracleBest& best);

}  // namespace povwall::trace
