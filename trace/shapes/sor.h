// sor: a surface of revolution whose squared radius is a cubic in height per segment.
// As POV-Ray: the end caps, then the segments its bounding cylinders let through, each
// a cubic in the ray distance solved by POV-Ray's solver (pov_polysolve.h).
#pragma once

#include "trace/pov_bounds.h"
#include "trace/shapes/common.h"

namespace povwall::trace {

struct OracleRay;
struct OracleBest;

// ShapeHit::face of a sor: a segment's index, or one of these.
constexpr int kSorBase = -1, kSorCap = -2;

// The crossings along a unit direction from `o` whose world distance (object distance
// / `dir_length`) lies in (1e-4, 1e7), in POV-Ray's order (not sorted).
void intersect_sor(const Sor& s, const Point3& o, const Vector3& dir, Real dir_length,
                   ShapeHits& out);
Vector3 sor_normal(const Sor& s, const Point3& p, int face);
bool inside_sor(const Sor& s, const Point3& p);

void shape_hits(const Sor& s, const LocalRay& r, ShapeHits& out);
Vector3 shape_normal(const Sor& s, const ShapeHit& h);
bool shape_inside(const Sor& s, const Point3& p);
Bounds3 shape_bounds(const Sor& s);
PovBBox shape_pov_bbox(const Sor& s, const CompactTransform& xf);
constexpr bool shape_pov_tests_own_bbox(const Sor&) { return true; }
constexpr bool shape_convex(const Sor&) { return false; }
constexpr bool shape_invertible(const Sor&) { return true; }
bool shape_oracle_first(const Sor& s, const OracleRay& r, OracleBest& best);

}  // namespace povwall::trace
