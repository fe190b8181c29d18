// quadric: A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y + I z + J = 0, kept
// in world coefficients as POV-Ray 3.7's Quadric (notes: shape-poly-quadric.md 4-6;
// core/quadric.h folds the transforms in). The world ray is met as it is, not
// normalised; POV-Ray tests the quadric's own float box first, which can cull visible
// parts (its box bugs).
#pragma once

#include "trace/pov_bounds.h"
#include "trace/shapes/common.h"

namespace povwall::trace {

struct OracleRay;
struct OracleBest;

constexpr Real kQuadricDepthTolerance = 1e-6;

// Q at a world point, grouped as POV-Ray's inside test.
Real quadric_value(const Quadric& q, const Point3& p);

void shape_hits(const Quadric& q, const LocalRay& r, ShapeHits& out);
Vector3 shape_normal(const Quadric& q, const ShapeHit& h);
bool shape_inside(const Quadric& q, const Point3& p);
bool shape_inside_inverted(const Quadric& q, const Point3& p);
Bounds3 shape_bounds(const Quadric& q);
PovBBox shape_pov_bbox(const Quadric& q, const CompactTransform& xf);
constexpr bool shape_pov_tests_own_bbox(const Quadric&) { return true; }
constexpr bool shape_convex(const Quadric&) { return false; }
constexpr bool shape_invertible(const Quadric&) { return true; }
bool shape_oracle_first(const Quadric& q, const OracleRay& r, OracleBest& best);

}  // namespace povwall::trace
