// mesh and mesh2: triangles over shared single-precision vertices. Outside CSG the
// prepared scene splits a mesh into its triangles; these operations serve CSG, the
// oracle and bounds.
#pragma once

#include "trace/pov_bounds.h"
#include "trace/shapes/common.h"

namespace povwall::trace {

struct OracleRay;
struct OracleBest;

// Whether the prepared scene traces this object as triangles of its own in the octree: a
// mesh used once, not inverse, not clipped. Copies (Mesh::copies), inverse and clipped
// meshes and those in CSG meet rays whole, in their own space, through the face tree.
bool mesh_as_triangles(const Object& o);

// A face's corners as POV-Ray stores them (single precision).
void mesh_face_corners(const Mesh& m, const Mesh::Face& f, Point3 (&p)[3]);

// Hits carry the face's index in `face`.
void shape_hits(const Mesh& m, const LocalRay& r, ShapeHits& out);
// A mesh without inside_vector (and with its box tree) reports only the hits up to its
// nearest (POV-Ray's tree walk stops there), the nearest kept by its clip: the clip is
// tested inside the search.
bool mesh_stops_at_nearest(const Mesh& m);
void shape_hits(const Mesh& m, const LocalRay& r, const ShapeClip* clip, ShapeHits& out);
Vector3 shape_normal(const Mesh& m, const ShapeHit& h);
// Solid only with an inside_vector (as in POV-Ray): a point is inside when a ray from it
// along that vector crosses the triangles an odd number of times.
bool shape_inside(const Mesh& m, const Point3& p);
bool shape_inside_inverted(const Mesh& m, const Point3& p);
Bounds3 shape_bounds(const Mesh& m);
PovBBox shape_pov_bbox(const Mesh& m, const CompactTransform& xf);
constexpr bool shape_pov_tests_own_bbox(const Mesh&) { return true; }
constexpr bool shape_convex(const Mesh&) { return false; }
constexpr bool shape_invertible(const Mesh&) { return true; }
// Without an inside_vector a mesh holds nothing, inverted or not.
bool shape_has_no_inside(const Mesh& m);
bool shape_oracle_first(const Mesh& m, const OracleRay& r, OracleBest& best);

}  // namespace povwall::trace
