#include "trace/shapes/disc.h"

#include <cmath>

#include "trace/shapes/oracle_math.h"

namespace povwall::trace {

void intersect_disc(const Disc& d, const Point3& o, const Vector3& dir, Crossings& out,
                    Real min_t) {
    Vector3 n = normalize(d.normal);
    Real nd = dot(n, dir);
    if (std::fabs(nd) < kPovEpsilon) return;
    Real t = dot(n, d.centre - o) / nd;
    if (t <= min_t) return;
    Vector3 q = o + dir * t - d.centre;
    Real r2 = dot(q, q);
    if (r2 <= d.radius * d.radius && r2 >= d.hole_radius * d.hole_radius) out.add(t, 0);
}

void shape_hits(const Disc& d, const LocalRay& r, ShapeHits& out) {
    Crossings cs;
    intersect_disc(d, r.origin, r.unit, cs, kPlaneTolerance * r.length);
    add_unit_crossings(cs, r, out);
}

Vector3 shape_normal(const Disc& d, const ShapeHit&) { return d.normal; }

// POV-Ray's Disc::Inside: the half-space behind the disc's plane (against its normal),
// the plane itself outside; CSG and clips use it like a plane's.
bool shape_inside(const Disc& d, const Point3& p) {
    return dot(p - d.centre, d.normal) < 0;
}

Bounds3 shape_bounds(const Disc& d) {
    return {d.centre - Vector3(d.radius), d.centre + Vector3(d.radius)};
}

PovBBox shape_pov_bbox(const Disc& s, const CompactTransform& xf) {
    const Real nl = length(s.normal);
    if (!(nl > 0)) return pov_infinite_bbox();
    // The canonical box is [-r, r]^2 x [-SMALL_TOLERANCE, SMALL_TOLERANCE].
    const Real r = s.radius;
    Vector3 ex, ey;
    const Vector3 n = s.normal / nl;
    pov_canonical_frame(n, ex, ey);
    return pov_bbox(
        pov_corners_bounds(Bounds3{{-r, -r, -kSmallTolerance}, {r, r, kSmallTolerance}},
                           [&](const Point3& p) {
                               return xf.point(s.centre + ex * p.x + ey * p.y + n * p.z);
                           }));
}

bool shape_oracle_first(const Disc& s, const OracleRay& r, OracleBest& best) {
    V3 n(normalize(s.normal));
    HP nd = dot(n, r.d);
    if (abs(nd) < HP(kPovEpsilon)) return true;
    HP t = dot(n, V3(s.centre) - r.o) / nd;
    V3 q = r.o + r.d * t - V3(s.centre);
    HP r2 = dot(q, q);
    if (r2 <= HP(s.radius) * s.radius && r2 >= HP(s.hole_radius) * s.hole_radius)
        best.offer(t, kPlaneTolerance);
    return true;
}

}  // namespace povwall::trace
