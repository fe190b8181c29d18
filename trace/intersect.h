// Ray-shape intersection in object space, with POV-Ray's per-shape depth tolerances.
//
// Each function appends the ray parameters of its surface crossings (object-space
// distances along a unit direction) to `out`, in increasing order, and can say whether a
// point is inside. The tracer handles transforms, MIN_ISECT_DEPTH and CSG on top of
// these.
#pragma once

#include "core/scene.h"
#include "trace/roots.h"

namespace povwall::trace {

// POV-Ray's minimum accepted hit depths (see docs/pov-semantics notes): per shape, then
// 1e-4 world distance for every hit. Each shape applies its own in the space its
// 3.7 code does: world distance for the box, disc, triangle, plane and torus (their depth
// is compared after the division by the transformed direction's length, or the direction
// is never normalised), object space along a unit direction for the ellipsoid, cone,
// cylinder and polygon.
constexpr Real kSphereTolerance = 1e-6;
constexpr Real kBoxTolerance = 1e-6;
constexpr Real kPlaneTolerance = 1e-6;
constexpr Real kConeTolerance = 1e-9;
constexpr Real kTorusTolerance = 1e-4;
constexpr Real kTriangleTolerance = 1e-6;
constexpr Real kPolygonTolerance = 1e-8;
constexpr Real kMinIsectDepth = 1e-4;
constexpr Real kPovEpsilon = 1e-10;
constexpr Real kMaxDistance = 1e7;

struct Crossing {
    Real t;
    int face;  // shape-specific: which surface part (for the normal)
};

// Up to this many crossings per shape (a torus has 4).
constexpr int kMaxCrossings = 4;
struct Crossings {
    Crossing c[kMaxCrossings];
    int n = 0;
    void add(Real t, int face) {
        if (n < kMaxCrossings) c[n++] = {t, face};
    }
};

// `dir` must be unit length. Returns crossings with t > the shape's depth tolerance.
void intersect_sphere(const Sphere& s, const Point3& o, const Vector3& dir,
                      Crossings& out);
void intersect_box(const Box& b, const Point3& o, const Vector3& dir, Crossings& out);
// POV-Ray's box (3.7:source/backend/shape/boxes.cpp, Box::Intersect and
// All_Intersections): the slabs in object space with the direction as the inverse
// transform leaves it, not normalised, so `t` is the ray's own parameter (the world
// distance). The interval starts at [0, BOUND_HUGE]; x narrows it exactly, y and z only
// where they move an end by more than kBoxCloseTolerance, and an entry within that of the
// current one is never compared with the exit. So a box thinner than 1e-6 along the ray
// is met wherever its slabs nearly overlap. Where two faces are that close, the face
// kept is the one the direction points at most directly (y against x; z against the
// axis of the face so far). The entry counts above kBoxTolerance, the exit always; no
// hit when the exit is below kBoxTolerance.
constexpr Real kBoxCloseTolerance = 1e-6;
constexpr Real kBoxBoundHuge = 2e10;
void intersect_box_pov(const Box& b, const Point3& o, const Vector3& dir, Crossings& out);
void intersect_plane(const Plane& p, const Point3& o, const Vector3& dir, Crossings& out,
                     Real min_t = kPlaneTolerance);
void intersect_cylinder(const Cylinder& c, const Point3& o, const Vector3& dir,
                        Crossings& out);
void intersect_cone(const Cone& c, const Point3& o, const Vector3& dir, Crossings& out);
// `min_t`: the smallest crossing kept, in the units of `dir` (callers turn the world
// tolerance into object units).
void intersect_disc(const Disc& d, const Point3& o, const Vector3& dir, Crossings& out,
                    Real min_t = kPlaneTolerance);
void intersect_triangle(const Point3 p[3], const Point3& o, const Vector3& dir,
                        Crossings& out, Real min_t = kTriangleTolerance);
// POV-Ray's degenerate triangle: its normal (P1 - P2) x (P3 - P2) has length exactly 0
// (Triangle::Compute_Triangle, 3.7:source/backend/shape/triangle.cpp:314). It has no
// normal, so it is never hit; a tiny triangle (edges of 1e-6) still is.
inline bool degenerate_triangle(const Point3 p[3]) {
    return length(cross(p[0] - p[1], p[2] - p[1])) == 0;
}
// POV-Ray's degenerate polygon (Polygon::Compute_Polygon, 3.7:source/backend/shape/
// polygon.cpp:672): no point after the first more than sqrt(EPSILON) = 1e-5 from it, or
// none after that one also 1e-5 from the first and spanning a parallelogram of area over
// 1e-5 with them. Polygons this small are never hit.
bool degenerate_polygon(const Polygon& p);
void intersect_torus(const Torus& t, const Point3& o, const Vector3& dir, Crossings& out,
                     Real min_t = kTorusTolerance);
// The torus's quartic along a ray: crossings are shift + the roots of c in (lo, hi].
// False when the ray misses the bounding sphere. Shared by the tracer, the solver
// benchmark and tests.
struct TorusQuartic {
    Real c[5], lo, hi, shift;
};
bool torus_quartic(const Torus& t, const Point3& o, const Vector3& dir, TorusQuartic& q,
                   Real min_t = kTorusTolerance);
// Even-odd rule over all edges of the point list (sub-polygons closed by repeating their
// first point, as POV-Ray writes them); the plane is the points' Newell plane.
void intersect_polygon(const Polygon& p, const Point3& o, const Vector3& dir,
                       Crossings& out);
Vector3 polygon_normal(const Polygon& p);
// The polygon's normal with the sign POV-Ray gives its surface: u x v, u from the first
// point to the first point apart from it, v to the next point off their line. (Which side
// is "outside" matters for interior_texture; Newell's normal can point the other way
// when the first corner is a reflex one.)
Vector3 pov_polygon_normal(const Polygon& p);
// A flat triangle's normal with POV-Ray's sign, (p0 - p1) x (p2 - p1) (Triangle and mesh
// triangles alike; unnormalised).
inline Vector3 pov_triangle_normal(const Point3 (&p)[3]) {
    return cross(p[0] - p[1], p[2] - p[1]);
}

// `x` rounded to single precision. Out of line on purpose: inlined into a Vector3 built
// from three such values, GCC 12.2's SLP vectorizer at -O3 drops the round trip of two of
// them (the double -> float -> double pair comes out unchanged).
Real round_to_float(Real x);
// A mesh vertex as POV-Ray stores it: single precision (SNGL_VECT, Mesh_Hash_Vertex).
inline Point3 single_precision(const Point3& p) {
    return {round_to_float(p.x), round_to_float(p.y), round_to_float(p.z)};
}

// Outward surface normal (object space, not normalised necessarily) at a crossing.
Vector3 sphere_normal(const Sphere& s, const Point3& p);
Vector3 box_normal(const Box& b, int face);
Vector3 cylinder_normal(const Cylinder& c, const Point3& p, int face);
Vector3 cone_normal(const Cone& c, const Point3& p, int face);
Vector3 torus_normal(const Torus& t, const Point3& p);
// The vertex normals `n` interpolated at p (unnormalised).
Vector3 smooth_triangle_normal(const Point3 (&corner)[3], const Vector3* n,
                               const Point3& p);

// Inside tests (object space), used by CSG.
bool inside_sphere(const Sphere& s, const Point3& p);
bool inside_box(const Box& b, const Point3& p);
bool inside_plane(const Plane& pl, const Point3& p);
bool inside_cylinder(const Cylinder& c, const Point3& p);
bool inside_cone(const Cone& c, const Point3& p);
bool inside_torus(const Torus& t, const Point3& p);

}  // namespace povwall::trace
