// parametric: the surface (X, Y, Z)(u, v) over a uv rectangle inside a box or sphere, as
// POV-Ray 3.7's Parametric (fpmetric.cpp). Along the ray (object space, world distances,
// from 4 * accuracy past the container's entry to its exit) the rectangle is split
// depth first, lower half first, across its longer side; a piece is dropped where the
// ray's span through its x, y or z bounds (core/parametric.h, or the precomputed ones)
// misses the container's, another axis's, or starts past the best hit so far; a piece
// narrower than `accuracy` in uv or in those spans is a hit at the start of its last
// axis's span. One hit (the nearest), its uv the piece's low corner; the normal is the
// cross product of forward differences of step `accuracy` in u and v; no inside.
#pragma once

#include "trace/pov_bounds.h"
#include "trace/shapes/common.h"

namespace povwall::trace {

struct OracleRay;
struct OracleBest;

// Hits: param = u, param2 = v (the surface coordinates uv_mapping reads).
void shape_hits(const Parametric& s, const LocalRay& r, ShapeHits& out);
Vector3 shape_normal(const Parametric& s, const ShapeHit& h);
bool shape_inside(const Parametric& s, const Point3& p);  // a surface: never
Bounds3 shape_bounds(const Parametric& s);
PovBBox shape_pov_bbox(const Parametric& s, const CompactTransform& xf);
constexpr bool shape_pov_tests_own_bbox(const Parametric&) { return true; }
constexpr bool shape_convex(const Parametric&) { return false; }
constexpr bool shape_invertible(const Parametric&) { return false; }
constexpr bool shape_has_no_inside(const Parametric&) { return true; }
// The nearest point of the surface on the ray: the uv rectangle cut until the pieces'
// sampled boxes (with a safety margin from the functions' sampled slopes) are tiny,
// then Newton on S(u, v) = o + t d from the nearest candidates.
bool shape_oracle_first(const Parametric& s, const OracleRay& r, OracleBest& best);

}  // namespace povwall::trace
