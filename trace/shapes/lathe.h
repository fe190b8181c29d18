// lathe: a spline profile (linear, quadratic, cubic or Bezier) turned about y. As
// POV-Ray: the segments its bounding cylinders let through, each the polynomial in the
// spline parameter t (degree 2, 4 or 6) solved by POV-Ray's solver (pov_polysolve.h).
#pragma once

#include "trace/pov_bounds.h"
#include "trace/shapes/common.h"

namespace povwall::trace {

struct OracleRay;
struct OracleBest;

// The crossings along a unit direction from `o` whose world distance (object distance
// / `dir_length`) lies in (1e-4, 1e7), in POV-Ray's order (not sorted); each hit's face
// is its segment and `param` its t. With `nearest_only` (the caller keeps only the
// nearest crossing in [want_lo, want_hi)), a segment whose heights put all its crossings
// beyond want_hi, or beyond a crossing found in that range, is not solved; with
// `any_crossing` too, the search ends at the first segment with a crossing there.
void intersect_lathe(const Lathe& s, const Point3& o, const Vector3& dir, Real dir_length,
                     ShapeHits& out, bool nearest_only = false, Real want_lo = 0,
                     Real want_hi = kInfinity, bool any_crossing = false);
Vector3 lathe_normal(const Lathe& s, const Point3& p, int segment, Real t);
bool inside_lathe(const Lathe& s, const Point3& p);

void shape_hits(const Lathe& s, const LocalRay& r, ShapeHits& out);
Vector3 shape_normal(const Lathe& s, const ShapeHit& h);
bool shape_inside(const Lathe& s, const Point3& p);
Bounds3 shape_bounds(const Lathe& s);
PovBBox shape_pov_bbox(const Lathe& s, const CompactTransform& xf);
constexpr bool shape_pov_tests_own_bbox(const Lathe&) { return true; }
constexpr bool shape_convex(const Lathe&) { return false; }
constexpr bool shape_invertible(const Lathe&) { return true; }
bool shape_oracle_first(const Lathe& s, const OracleRay& r, OracleBest& best);

}  // namespace povwall::trace
