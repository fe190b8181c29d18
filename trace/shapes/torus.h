// torus: a ring of radius `major` around y, of tube radius `minor`.
#pragma once

#include "trace/pov_bounds.h"
#include "trace/shapes/common.h"

namespace povwall::trace {

struct OracleRay;
struct OracleBest;

void intersect_torus(const Torus& t, const Point3& o, const Vector3& dir, Crossings& out,
                     Real min_t = kTorusTolerance);
// The torus's quartic along a ray: crossings are shift + the roots of c in (lo, hi].
// False when the ray misses the bounding sphere. The solver benchmark's cases (the
// tracer solves POV-Ray's own quartic: intersect_torus).
struct TorusQuartic {
    Real c[5], lo, hi, shift;
};
bool torus_quartic(const Torus& t, const Point3& o, const Vector3& dir, TorusQuartic& q,
                   Real min_t = kTorusTolerance);
Vector3 torus_normal(const Torus& t, const Point3& p);
bool inside_torus(const Torus& t, const Point3& p);

void shape_hits(const Torus& t, const LocalRay& r, ShapeHits& out);
Vector3 shape_normal(const Torus& t, const ShapeHit& h);
bool shape_inside(const Torus& t, const Point3& p);
Bounds3 shape_bounds(const Torus& t);
PovBBox shape_pov_bbox(const Torus& t, const CompactTransform& xf);
constexpr bool shape_pov_tests_own_bbox(const Torus&) { return true; }
constexpr bool shape_convex(const Torus&) { return false; }
constexpr bool shape_invertible(const Torus&) { return true; }
bool shape_oracle_first(const Torus& t, const OracleRay& r, OracleBest& best);

}  // namespace povwall::trace
