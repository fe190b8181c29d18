#include "trace/shapes/plane.h"

#include <cmath>

#include "trace/shapes/oracle_math.h"

namespace povwall::trace {

void intersect_plane(const Plane& p, const Point3& o, const Vector3& dir, Crossings& out,
                     Real min_t) {
    Real nd = dot(p.normal, dir);
    if (std::fabs(nd) < kPovEpsilon) return;
    Real t = (p.distance - dot(p.normal, o)) / nd;
    if (t > min_t && t < kMaxDistance) out.add(t, 0);
}

// POV-Ray's Plane::Inside: within EPSILON of the surface counts as inside; its Invert
// negates the equation, so the surface is inside the inverted plane too.
bool inside_plane(const Plane& pl, const Point3& p) {
    return dot(pl.normal, p) - pl.distance < kPovEpsilon;
}

void shape_hits(const Plane& p, const LocalRay& r, ShapeHits& out) {
    Crossings cs;
    intersect_plane(p, r.origin, r.unit, cs, kPlaneTolerance * r.length);
    add_unit_crossings(cs, r, out);
}

Vector3 shape_normal(const Plane& p, const ShapeHit&) { return p.normal; }

bool shape_inside(const Plane& p, const Point3& q) { return inside_plane(p, q); }

bool shape_inside_inverted(const Plane& p, const Point3& q) {
    return p.distance - dot(p.normal, q) < kPovEpsilon;
}

Bounds3 shape_bounds(const Plane&) { return Bounds3::everything(); }

PovBBox shape_pov_bbox(const Plane&, const CompactTransform&) {
    return pov_infinite_bbox();
}

bool shape_oracle_first(const Plane& s, const OracleRay& r, OracleBest& best) {
    V3 n(s.normal);
    HP nd = dot(n, r.d);
    if (abs(nd) < HP(kPovEpsilon)) return true;
    HP t = (HP(s.distance) - dot(n, r.o)) / nd;
    if (t < kMaxDistance) best.offer(t, kPlaneTolerance);
    return true;
}

}  // namespace povwall::trace
