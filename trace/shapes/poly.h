// poly, cubic, quartic, polynomial: the algebraic surface F(x, y, z) = 0 of a Poly, as
// POV-Ray 3.7's Poly object (notes: shape-poly-quadric.md sections 1-4, 6.1).
//
// The coefficients run over the terms x^i y^j z^k, i + j + k <= N, in POV-Ray's order:
// i from N down to 0, then j from N - i down to 0, then k from N - i - j down to 0.
// A ray is met in object space along the unit direction: order 2 by POV-Ray's own
// quadratic, higher orders by expanding F along the ray and POV-Ray's solver
// (core/pov_polysolve.h, root elimination 1e-4). POV-Ray never tests a poly's own box;
// unclipped it is infinite.
#pragma once

#include "core/poly_terms.h"
#include "trace/pov_bounds.h"
#include "trace/shapes/common.h"

namespace povwall::trace {

struct OracleRay;
struct OracleBest;

// POV-Ray's minimum object-space depth along the unit direction, and the inside margin
// on F (an absolute tolerance: it depends on the scale of the coefficients).
constexpr Real kPolyDepthTolerance = 1e-4;
constexpr Real kPolyInsideTolerance = 1e-4;

// The roots along `unit` from `origin`, in POV-Ray's order (not filtered); returns
// their count (at most the order).
int poly_roots(const Poly& s, const Point3& origin, const Vector3& unit, Real* roots);
// F at an object-space point, summed as POV-Ray's inside test (zero terms skipped).
Real poly_value(const Poly& s, const Point3& p);
Vector3 poly_gradient(const Poly& s, const Point3& p);

void shape_hits(const Poly& s, const LocalRay& r, ShapeHits& out);
Vector3 shape_normal(const Poly& s, const ShapeHit& h);
bool shape_inside(const Poly& s, const Point3& p);
Bounds3 shape_bounds(const Poly& s);                                // everything
PovBBox shape_pov_bbox(const Poly& s, const CompactTransform& xf);  // infinite
constexpr bool shape_pov_tests_own_bbox(const Poly&) { return false; }
constexpr bool shape_convex(const Poly&) { return false; }
constexpr bool shape_invertible(const Poly&) { return true; }
bool shape_oracle_first(const Poly& s, const OracleRay& r, OracleBest& best);

}  // namespace povwall::trace
