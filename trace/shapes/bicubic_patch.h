// bicubic_patch: the flat pieces of a Bezier patch (core/bicubic_patch.h), met as POV-Ray
// 3.7 meets them: bounding spheres down the tree, two triangles per leaf, normals
// interpolated from the patch's exact ones at the triangle's corners.
#pragma once

#include "trace/pov_bounds.h"
#include "trace/shapes/common.h"

namespace povwall::trace {

struct OracleRay;
struct OracleBest;

// Hits: face = 2 * leaf + triangle, (s, s2) its barycentric coordinates.
void shape_hits(const BicubicPatch& p, const LocalRay& r, ShapeHits& out);
Vector3 shape_normal(const BicubicPatch& p, const ShapeHit& h);
bool shape_inside(const BicubicPatch& p, const Point3& q);  // a surface: never
Bounds3 shape_bounds(const BicubicPatch& p);
PovBBox shape_pov_bbox(const BicubicPatch& p, const CompactTransform& xf);
constexpr bool shape_pov_tests_own_bbox(const BicubicPatch&) { return true; }
constexpr bool shape_convex(const BicubicPatch&) { return false; }
constexpr bool shape_invertible(const BicubicPatch&) { return false; }
constexpr bool shape_has_no_inside(const BicubicPatch&) { return true; }
bool shape_oracle_first(const BicubicPatch& p, const OracleRay& r, OracleBest& best);

}  // namespace povwall::trace
