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

// POV-Ray's minimum accepted hit depths (see docs/pov-semantics notes): per shape, in
// object space, then 1e-4 world distance for every hit.
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
void intersect_plane(const Plane& p, const Point3& o, const Vector3& dir, Crossings& out);
void intersect_cylinder(const Cylinder& c, const Point3& o, const Vector3& dir,
                        Crossings& out);
void intersect_cone(const Cone& c, const Point3& o, const Vector3& dir, Crossings& out);
void intersect_disc(const Disc& d, const Point3& o, const Vector3& dir, Crossings& out);
void intersect_triangle(const Point3 p[3], const Point3& o, const Vector3& dir,
                        Crossings& out);
// POV-Ray's degenerate triangle: coincident or collinear corners (|edge x edge| < 1e-10).
// It has no normal, so it is never hit.
inline bool degenerate_triangle(const Point3 p[3]) {
    return length(cross(p[1] - p[0], p[2] - p[0])) < 1e-10;
}
void intersect_torus(const Torus& t, const Point3& o, const Vector3& dir, Crossings& out);
// The torus's quartic along a ray: crossings are shift + the roots of c in (lo, hi].
// False when the ray misses the bounding sphere. Shared by the tracer, the solver
// benchmark and tests.
struct TorusQuartic {
    Real c[5], lo, hi, shift;
};
bool torus_quartic(const Torus& t, const Point3& o, const Vector3& dir, TorusQuartic& q);
// Even-odd rule over all edges of the point list (sub-polygons closed by repeating their
// first point, as POV-Ray writes them); the plane is the points' Newell plane.
void intersect_polygon(const Polygon& p, const Point3& o, const Vector3& dir,
                       Crossings& out);
Vector3 polygon_normal(const Polygon& p);

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
