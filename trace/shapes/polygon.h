// polygon: one or more closed loops in a plane, filled by the even-odd rule.
#pragma once

#include "trace/pov_bounds.h"
#include "trace/shapes/common.h"

namespace povwall::trace {

struct OracleRay;
struct OracleBest;

// Even-odd rule over all edges of the point list (sub-polygons closed by repeating their
// first point, as POV-Ray writes them); the plane is the points' Newell plane.
void intersect_polygon(const Polygon& p, const Point3& o, const Vector3& dir,
                       Crossings& out);
// POV-Ray's degenerate polygon (Polygon::Compute_Polygon, 3.7:source/backend/shape/
// polygon.cpp:672): no point after the first more than sqrt(EPSILON) = 1e-5 from it, or
// none after that one also 1e-5 from the first and spanning a parallelogram of area over
// 1e-5 with them. Polygons this small are never hit.
bool degenerate_polygon(const Polygon& p);
Vector3 polygon_normal(const Polygon& p);
// The polygon's normal with the sign POV-Ray gives its surface: u x v, u from the first
// point to the first point apart from it, v to the next point off their line. (Which side
// is "outside" matters for interior_texture; Newell's normal can point the other way
// when the first corner is a reflex one.)
Vector3 pov_polygon_normal(const Polygon& p);

void shape_hits(const Polygon& p, const LocalRay& r, ShapeHits& out);
Vector3 shape_normal(const Polygon& p, const ShapeHit& h);
bool shape_inside(const Polygon& p, const Point3& q);
Bounds3 shape_bounds(const Polygon& p);
PovBBox shape_pov_bbox(const Polygon& p, const CompactTransform& xf);
constexpr bool shape_pov_tests_own_bbox(const Polygon&) { return true; }
constexpr bool shape_convex(const Polygon&) { return true; }
constexpr bool shape_invertible(const Polygon&) { return false; }
constexpr bool shape_has_no_inside(const Polygon&) { return true; }
bool shape_oracle_first(const Polygon& p, const OracleRay& r, OracleBest& best);

}  // namespace povwall::trace
