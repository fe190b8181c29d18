// disc: a flat ring around `centre` facing `normal`, from hole_radius to radius.
#pragma once

#include "trace/pov_bounds.h"
#include "trace/shapes/common.h"

namespace povwall::trace {

struct OracleRay;
struct OracleBest;

// `min_t`: the smallest crossing kept, in the units of `dir` (callers turn the world
// tolerance into object units).
void intersect_disc(const Disc& d, const Point3& o, const Vector3& dir, Crossings& out,
                    Real min_t = kPlaneTolerance);

void shape_hits(const Disc& d, const LocalRay& r, ShapeHits& out);
Vector3 shape_normal(const Disc& d, const ShapeHit& h);
bool shape_inside(const Disc& d, const Point3& p);
Bounds3 shape_bounds(const Disc& d);
PovBBox shape_pov_bbox(const Disc& d, const CompactTransform& xf);
constexpr bool shape_pov_tests_own_bbox(const Disc&) { return true; }
constexpr bool shape_convex(const Disc&) { return true; }
constexpr bool shape_invertible(const Disc&) { return true; }
bool shape_oracle_first(const Disc& d, const OracleRay& r, OracleBest& best);

}  // namespace povwall::trace
