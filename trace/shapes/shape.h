// The shape layer: every operation the tracer, the octree, POV-Ray's bounding model and
// the numerics oracle need of a leaf shape, dispatched over ShapeData.
//
// Each shape lives in its own file here (its kernels and its shape_* overloads); each
// function below visits every alternative, so a shape that lacks an operation is a
// compile error, not an object that silently vanishes. To add a shape: its data in
// core/scene.h (ShapeData), a file here with the overloads, and the include below.
// CSG is not a leaf: its operations combine its children's (trace/prepared_scene.cpp,
// pov_bounds.cpp) and a leaf operation called on one is a programming error.
#pragma once

#include "trace/shapes/bicubic_patch.h"
#include "trace/shapes/blob.h"
#include "trace/shapes/box.h"
#include "trace/shapes/common.h"
#include "trace/shapes/cylinder_cone.h"
#include "trace/shapes/disc.h"
#include "trace/shapes/height_field.h"
#include "trace/shapes/isosurface.h"
#include "trace/shapes/julia_fractal.h"
#include "trace/shapes/lathe.h"
#include "trace/shapes/mesh.h"
#include "trace/shapes/ovus.h"
#include "trace/shapes/parametric.h"
#include "trace/shapes/plane.h"
#include "trace/shapes/poly.h"
#include "trace/shapes/polygon.h"
#include "trace/shapes/prism.h"
#include "trace/shapes/quadric.h"
#include "trace/shapes/sor.h"
#include "trace/shapes/sphere.h"
#include "trace/shapes/sphere_sweep.h"
#include "trace/shapes/superellipsoid.h"
#include "trace/shapes/text.h"
#include "trace/shapes/torus.h"
#include "trace/shapes/triangle.h"

namespace povwall::trace {

// The world ray in the leaf's own space.
LocalRay leaf_ray(const Object& leaf, const Ray& ray);
// The leaf's surface crossings along `r`, in the order its shape finds them.
void leaf_hits(const Object& leaf, const LocalRay& r, ShapeHits& out);
// The outward normal at a hit, in the leaf's own space (not normalised).
Vector3 leaf_normal(const Object& leaf, const ShapeHit& h);
// The unit outward normal at a hit in world space (the leaf's normal through its
// transform; a smooth height field blends normals already transformed, as POV-Ray's).
Vector3 leaf_world_normal(const Object& leaf, const ShapeHit& h);
// The same at the crossing's world point (`world`: where the ray meets it).
Vector3 leaf_world_normal(const Object& leaf, const ShapeHit& h, const Point3& world);
// `p` in the leaf's own space; surfaces (triangle, disc, polygon, a mesh without an
// inside_vector) have no inside.
bool leaf_inside(const Object& leaf, const Point3& p);
// The leaf's inside once POV-Ray's Invert has turned it (the caller checks
// leaf_invertible): the complement, except where its Invert keeps the surface inside both
// ways (plane, quadric) or in neither (sphere).
bool leaf_inside_inverted(const Object& leaf, const Point3& p);
// Bounds in the leaf's own space; Bounds3::everything() for an infinite shape.
Bounds3 leaf_bounds(const Object& leaf);
// POV-Ray's box of the leaf (its Compute_BBox through the leaf's transform).
PovBBox leaf_pov_bbox(const Object& leaf);
// Whether POV-Ray's Find_Intersection tests the leaf's own box first.
bool leaf_pov_tests_own_bbox(const Object& leaf);
// Whether the surface is convex or flat: it cannot shadow one of its own lit points.
bool leaf_convex(const Object& leaf);
// Whether POV-Ray's Invert turns the leaf inside out. Triangles, polygons, bicubic
// patches and parametrics keep no inverted flag (their Invert does nothing): `inverse`
// and a difference leave their inside (none) and their normal as they are.
bool leaf_invertible(const Object& leaf);
// Whether the leaf has no inside however it is held (a surface: its shape's
// shape_has_no_inside; every other shape answers false).
bool leaf_never_inside(const Object& leaf);
// Whether a difference's Invert_Object turns a child after the first inside out (a CSG
// always; a leaf when it is invertible).
inline bool difference_inverts(const Object& child) {
    return std::holds_alternative<Csg>(child.shape) || leaf_invertible(child);
}
// How child i of a CSG held `inverted` is held for its inside test: inverted with the
// CSG, and once more as a difference's later part.
inline bool child_held_inverted(const Csg& csg, size_t i, bool inverted) {
    return inverted != (csg.kind == CsgKind::Difference && i > 0 &&
                        difference_inverts(csg.children[i]));
}
// The oracle's first accepted object-space t (false: the shape has no oracle).
bool leaf_oracle_first(const Object& leaf, const OracleRay& r, OracleBest& best);

}  // namespace povwall::trace
