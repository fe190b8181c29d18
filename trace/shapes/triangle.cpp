#include "trace/shapes/triangle.h"

#include <cmath>

#include "trace/shapes/oracle_math.h"

namespace povwall::trace {

void intersect_triangle(const Point3 p[3], const Point3& o, const Vector3& dir,
                        Crossings& out, Real min_t) {
    Vector3 e1 = p[1] - p[0], e2 = p[2] - p[0];
    Vector3 pv = cross(dir, e2);
    Real det = dot(e1, pv);
    if (std::fabs(det) < 1e-300) return;
    Real inv = 1 / det;
    Vector3 tv = o - p[0];
    Real u = dot(tv, pv) * inv;
    if (u < 0 || u > 1) return;
    Vector3 qv = cross(tv, e1);
    Real v = dot(dir, qv) * inv;
    if (v < 0 || u + v > 1) return;
    Real t = dot(e2, qv) * inv;
    if (t > min_t) out.add(t, 0);
}

Vector3 smooth_triangle_normal(const Point3 (&corner)[3], const Vector3* n,
                               const Point3& q) {
    // Barycentric interpolation of the vertex normals.
    Vector3 e1 = corner[1] - corner[0], e2 = corner[2] - corner[0], w = q - corner[0];
    Real d00 = dot(e1, e1), d01 = dot(e1, e2), d11 = dot(e2, e2);
    Real d20 = dot(w, e1), d21 = dot(w, e2);
    Real den = d00 * d11 - d01 * d01;
    if (den == 0) return cross(e1, e2);
    Real v = (d11 * d20 - d01 * d21) / den, u2 = (d00 * d21 - d01 * d20) / den;
    return n[0] * (1 - v - u2) + n[1] * v + n[2] * u2;
}

namespace {

void corner_hits(const Point3 (&p)[3], const LocalRay& r, ShapeHits& out) {
    if (degenerate_triangle(p)) return;
    Crossings cs;
    intersect_triangle(p, r.origin, r.unit, cs, kTriangleTolerance * r.length);
    add_unit_crossings(cs, r, out);
}

Bounds3 corner_bounds(const Point3 (&p)[3]) {
    Bounds3 b;
    for (const Point3& q : p) b.extend(q);
    return b;
}

// Triangles keep no transform: their corners are moved. Padded by EPSILON.
PovBBox corner_pov_bbox(const Point3 (&p)[3], const CompactTransform& xf) {
    Bounds3 b;
    for (const Point3& q : p) b.extend(xf.point(q));
    b.lo -= Vector3(kPovEpsilon);
    b.hi += Vector3(kPovEpsilon);
    return pov_bbox(b);
}

bool corner_oracle(const Point3 (&p)[3], const OracleRay& r, OracleBest& best) {
    if (degenerate_triangle(p)) return true;
    V3 q[3] = {V3(p[0]), V3(p[1]), V3(p[2])};
    oracle_triangle(q, r, best);
    return true;
}

}  // namespace

void shape_hits(const Triangle& t, const LocalRay& r, ShapeHits& out) {
    corner_hits(t.p, r, out);
}
Vector3 shape_normal(const Triangle& t, const ShapeHit&) {
    return pov_triangle_normal(t.p);
}
bool shape_inside(const Triangle&, const Point3&) { return false; }
Bounds3 shape_bounds(const Triangle& t) { return corner_bounds(t.p); }
PovBBox shape_pov_bbox(const Triangle& t, const CompactTransform& xf) {
    return corner_pov_bbox(t.p, xf);
}
bool shape_oracle_first(const Triangle& t, const OracleRay& r, OracleBest& best) {
    return corner_oracle(t.p, r, best);
}

void shape_hits(const SmoothTriangle& t, const LocalRay& r, ShapeHits& out) {
    // A zero first normal: the parser found it degenerate (POV-Ray never hits it).
    const Vector3& n0 = (*t.n)[0];
    if (n0.x == 0 && n0.y == 0 && n0.z == 0) return;
    corner_hits(t.p, r, out);
}
Vector3 shape_normal(const SmoothTriangle& t, const ShapeHit& h) {
    return smooth_triangle_normal(t.p, t.n->data(), h.p);
}
bool shape_inside(const SmoothTriangle&, const Point3&) { return false; }
Bounds3 shape_bounds(const SmoothTriangle& t) { return corner_bounds(t.p); }
PovBBox shape_pov_bbox(const SmoothTriangle& t, const CompactTransform& xf) {
    return corner_pov_bbox(t.p, xf);
}
bool shape_oracle_first(const SmoothTriangle& t, const OracleRay& r, OracleBest& best) {
    const Vector3& n0 = (*t.n)[0];
    if (n0.x == 0 && n0.y == 0 && n0.z == 0) return true;  // degenerate: never hit
    return corner_oracle(t.p, r, best);
}

}  // namespace povwall::trace
