// prism: closed 2-D curves swept along y (linear_sweep) or towards the origin
// (conic_sweep), as POV-Ray 3.7's Prism (3.7:source/backend/shape/prism.cpp).
#pragma once

#include "trace/pov_bounds.h"
#include "trace/shapes/common.h"

namespace povwall::trace {

struct OracleRay;
struct OracleBest;

// Faces of hits: kPrismBase, kPrismCap, or the wall segment's index (ShapeHit::s is the
// spline parameter there).
constexpr int kPrismBase = -1, kPrismCap = -2;

// The even-odd test of a point (u, v) of the curves' plane: crossings of the curves by
// the half line from it towards +u (POV-Ray's in_curve).
bool prism_in_curve(const Prism& p, Real u, Real v);

void shape_hits(const Prism& p, const LocalRay& r, ShapeHits& out);
Vector3 shape_normal(const Prism& p, const ShapeHit& h);
bool shape_inside(const Prism& p, const Point3& q);
Bounds3 shape_bounds(const Prism& p);
PovBBox shape_pov_bbox(const Prism& p, const CompactTransform& xf);
constexpr bool shape_pov_tests_own_bbox(const Prism&) { return true; }
constexpr bool shape_convex(const Prism&) { return false; }
constexpr bool shape_invertible(const Prism&) { return true; }
bool shape_oracle_first(const Prism& p, const OracleRay& r, OracleBest& best);

}  // namespace povwall::trace
