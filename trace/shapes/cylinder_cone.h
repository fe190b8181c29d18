// cylinder and cone: a solid of revolution between two end points, capped unless `open`.
#pragma once

#include "trace/pov_bounds.h"
#include "trace/shapes/common.h"

namespace povwall::trace {

struct OracleRay;
struct OracleBest;

// Faces: 0 the side, 1 the base cap, 2 the other cap.
void intersect_cylinder(const Cylinder& c, const Point3& o, const Vector3& dir,
                        Crossings& out);
void intersect_cone(const Cone& c, const Point3& o, const Vector3& dir, Crossings& out);
Vector3 cylinder_normal(const Cylinder& c, const Point3& p, int face);
Vector3 cone_normal(const Cone& c, const Point3& p, int face);
bool inside_cylinder(const Cylinder& c, const Point3& p);
bool inside_cone(const Cone& c, const Point3& p);

void shape_hits(const Cylinder& c, const LocalRay& r, ShapeHits& out);
Vector3 shape_normal(const Cylinder& c, const ShapeHit& h);
bool shape_inside(const Cylinder& c, const Point3& p);
Bounds3 shape_bounds(const Cylinder& c);
// The world box of the cylinder under `xf` (any affine map), as tight as its ends and its
// turned cross-section allow: a box of the local box's corners would grow by up to
// sqrt(2) across a slanted cylinder.
Bounds3 cylinder_world_bounds(const Cylinder& c, const Transform& xf);
Bounds3 cone_world_bounds(const Cone& c, const Transform& xf);
PovBBox shape_pov_bbox(const Cylinder& c, const CompactTransform& xf);
constexpr bool shape_pov_tests_own_bbox(const Cylinder&) { return true; }
inline bool shape_convex(const Cylinder& c) { return !c.open; }
constexpr bool shape_invertible(const Cylinder&) { return true; }
bool shape_oracle_first(const Cylinder& c, const OracleRay& r, OracleBest& best);

void shape_hits(const Cone& c, const LocalRay& r, ShapeHits& out);
Vector3 shape_normal(const Cone& c, const ShapeHit& h);
bool shape_inside(const Cone& c, const Point3& p);
Bounds3 shape_bounds(const Cone& c);
PovBBox shape_pov_bbox(const Cone& c, const CompactTransform& xf);
constexpr bool shape_pov_tests_own_bbox(const Cone&) { return true; }
inline bool shape_convex(const Cone& c) { return !c.open; }
constexpr bool shape_invertible(const Cone&) { return true; }
bool shape_oracle_first(const Cone& c, const OracleRay& r, OracleBest& best);

}  // namespace povwall::trace
