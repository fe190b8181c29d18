// julia_fractal: the slice of a 4-D Julia set, found by POV-Ray 3.7's ray march (steps
// from its distance estimate, at least 1 / precision, then bisection to 1e-7).
#pragma once

#include "trace/pov_bounds.h"
#include "trace/shapes/common.h"

namespace povwall::trace {

struct OracleRay;
struct OracleBest;

// Whether the object-space point is in the set (the iteration does not escape).
bool julia_inside(const JuliaFractal& j, const Point3& p);

// Hits carry their normal (ShapeHit::normal), found with the iteration at the hit.
void shape_hits(const JuliaFractal& j, const LocalRay& r, ShapeHits& out);
Vector3 shape_normal(const JuliaFractal& j, const ShapeHit& h);
bool shape_inside(const JuliaFractal& j, const Point3& p);
Bounds3 shape_bounds(const JuliaFractal& j);
PovBBox shape_pov_bbox(const JuliaFractal& j, const CompactTransform& xf);
constexpr bool shape_pov_tests_own_bbox(const JuliaFractal&) { return true; }
constexpr bool shape_convex(const JuliaFractal&) { return false; }
constexpr bool shape_invertible(const JuliaFractal&) { return true; }
// No oracle, for every algebra and function: the surface POV-Ray draws is what its march
// finds (steps of at least 1 / precision, bisection to 1e-7, and for exp ... pwr a plain
// iteration started from (x, y, y)), not the root of an equation a 50-digit solver could
// find; the same march in 50 digits would only measure its rounding. check-numerics
// counts the rays reaching a julia_fractal as unsupported.
bool shape_oracle_first(const JuliaFractal& j, const OracleRay& r, OracleBest& best);

}  // namespace povwall::trace
