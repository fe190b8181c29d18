#include "trace/shapes/ovus.h"

#include <algorithm>
#include <cmath>

#include "core/pov_polysolve.h"
#include "trace/roots_sturm.h"
#include "trace/shapes/oracle_math.h"

namespace povwall::trace {

namespace {

// POV-Ray's ROOT_TOLERANCE: the quartic's root elimination and the band residual.
constexpr Real kRootTolerance = 1e-4;
constexpr Real kUnset = -100;  // POV-Ray's "no crossing" depth

// A sphere's two crossings as POV-Ray finds them: only when the origin is inside or the
// centre lies ahead, and a half chord above EPSILON (tangent rays miss).
bool sphere_chord(const Point3& centre, Real radius2, const Point3& o, const Vector3& d,
                  Real& near, Real& far) {
    const Vector3 oc = centre - o;
    const Real oc2 = dot(oc, oc);
    const Real closest = dot(oc, d);
    if (!(oc2 < radius2 || closest > kPovEpsilon)) return false;
    const Real half2 = radius2 - oc2 + closest * closest;
    if (!(half2 > kPovEpsilon)) return false;
    const Real half = std::sqrt(half2);
    near = closest - half;
    far = closest + half;
    return true;
}

// The band's residual: squared distance from the profile circle's centre (across the
// axis) minus its squared radius.
Real band_residual(const Ovus& s, const Point3& p) {
    const Real rho = std::sqrt(p.x * p.x + p.z * p.z);
    const Real a = rho + s.band_offset, b = p.y - s.band_height;
    return a * a + b * b - s.band_radius * s.band_radius;
}

}  // namespace

void intersect_ovus(const Ovus& s, const Point3& o, const Vector3& d, Crossings& out) {
    Real depth[6] = {kUnset, kUnset, kUnset, kUnset, kUnset, kUnset};
    auto at = [&](Real t) { return o + d * t; };
    // A convex body is crossed at most twice: two sphere crossings on the sphere's own
    // part end the search.
    int on_part = 0;
    if (sphere_chord({0, 0, 0}, s.bottom_radius * s.bottom_radius, o, d, depth[0],
                     depth[1])) {
        on_part += at(depth[0]).y < s.band_bottom;
        on_part += at(depth[1]).y < s.band_bottom;
    }
    if (on_part <= 1 && sphere_chord({0, s.bottom_radius, 0}, s.top_radius * s.top_radius,
                                     o, d, depth[2], depth[3])) {
        on_part += at(depth[2]).y > s.band_top;
        on_part += at(depth[3]).y > s.band_top;
    }
    if (on_part <= 1) {
        const Point3 q = o - Vector3{0, s.band_height, 0};
        const Real R2 = s.band_offset * s.band_offset, r2 = s.band_radius * s.band_radius;
        const Real qy2 = q.y * q.y, dy2 = d.y * d.y, qdy = q.y * d.y;
        const Real k1 = q.x * q.x + q.z * q.z + qy2 - R2 - r2;
        const Real k2 = q.x * d.x + q.z * d.z + qdy;
        const Real c[5] = {1.0, 4.0 * k2, 2.0 * (k1 + 2.0 * (k2 * k2 + R2 * dy2)),
                           4.0 * (k2 * k1 + 2.0 * R2 * qdy),
                           k1 * k1 + 4.0 * R2 * (qy2 - r2)};
        Real roots[4];
        int n = pov_solve_polynomial(4, c, roots, s.sturm, kRootTolerance);
        // Only the band between the spheres, and only true roots (the outer part of the
        // torus and spurious roots fail the residual).
        while (n--) {
            const Point3 p = at(roots[n]);
            if (!(p.y > s.band_bottom && p.y < s.band_top)) continue;
            if (!(std::fabs(band_residual(s, p)) < kRootTolerance)) continue;
            // POV-Ray's two slots: a negative root in the first is replaced by the next,
            // a third root replaces the second.
            if (depth[4] < 0)
                depth[4] = roots[n];
            else
                depth[5] = roots[n];
        }
    }
    for (int i = 0; i < 6; ++i) {
        if (!(depth[i] > kPovEpsilon)) continue;
        const Real y = at(depth[i]).y;
        if (i < 2 && !(y < s.band_bottom)) continue;
        if (i >= 2 && i < 4 && !(y > s.band_top)) continue;
        out.add(depth[i], i / 2);
    }
}

Vector3 ovus_normal(const Ovus& s, const Point3& p, int part) {
    if (part == kOvusBottom) return p / s.bottom_radius;
    if (part == kOvusTop) return (p - Vector3{0, s.bottom_radius, 0}) / s.top_radius;
    // From the profile circle's centre, across the axis from the point.
    Vector3 n = p - Vector3{0, s.band_height, 0};
    const Real rho = std::sqrt(n.x * n.x + n.z * n.z);
    n.x += n.x * s.band_offset / rho;
    n.z += n.z * s.band_offset / rho;
    return n;
}

bool inside_ovus(const Ovus& s, const Point3& p) {
    if (dot(p, p) < s.bottom_radius * s.bottom_radius) return true;
    const Vector3 top = p - Vector3{0, s.bottom_radius, 0};
    if (dot(top, top) < s.top_radius * s.top_radius) return true;
    return p.y > s.band_bottom && p.y < s.band_top && band_residual(s, p) < 0;
}

void shape_hits(const Ovus& s, const LocalRay& r, ShapeHits& out) {
    Crossings cs;
    intersect_ovus(s, r.origin, r.unit, cs);
    // POV-Ray's order is by part; the tracer wants them along the ray.
    for (int i = 1; i < cs.n; ++i)  // a few: insertion sort
        for (int j = i; j > 0 && cs.c[j].t < cs.c[j - 1].t; --j)
            std::swap(cs.c[j], cs.c[j - 1]);
    add_unit_crossings(cs, r, out);
}

Vector3 shape_normal(const Ovus& s, const ShapeHit& h) {
    return ovus_normal(s, h.p, h.face);
}

bool shape_inside(const Ovus& s, const Point3& p) { return inside_ovus(s, p); }

Bounds3 shape_bounds(const Ovus& s) {
    const Real side =
        std::max({s.band_radius - s.band_offset, s.bottom_radius, s.top_radius});
    return {{-side, -s.bottom_radius, -side},
            {side, s.bottom_radius + s.top_radius, side}};
}

PovBBox shape_pov_bbox(const Ovus& s, const CompactTransform& xf) {
    Real side = s.band_radius - s.band_offset;
    if (side < s.bottom_radius) side = s.bottom_radius;
    if (side < s.top_radius) side = s.top_radius;
    return pov_transformed_bbox(
        {{-side, -s.bottom_radius, -side}, {side, s.bottom_radius + s.top_radius, side}},
        xf);
}

bool shape_oracle_first(const Ovus& s, const OracleRay& r, OracleBest& best) {
    // Each part exactly: the spheres' chords on their own parts, the torus quartic's
    // roots (Sturm in 50 digits) on the band.
    auto sphere = [&](const HP& cy, const HP& radius, bool below, const HP& limit) {
        const V3 oc = V3(HP(0), cy, HP(0)) - r.o;
        const HP closest = dot(oc, r.d);
        const HP half2 = radius * radius - dot(oc, oc) + closest * closest;
        if (!(half2 > HP(kPovEpsilon))) return;
        const HP half = sqrt(half2);
        for (const HP& t : {closest - half, closest + half}) {
            const HP y = r.o.y + r.d.y * t;
            if (below ? y < limit : y > limit) best.offer(t, kPovEpsilon);
        }
    };
    sphere(HP(0), HP(s.bottom_radius), true, HP(s.band_bottom));
    sphere(HP(s.bottom_radius), HP(s.top_radius), false, HP(s.band_top));
    const V3 q = r.o - V3(HP(0), HP(s.band_height), HP(0));
    const HP R2 = HP(s.band_offset) * s.band_offset,
             r2 = HP(s.band_radius) * s.band_radius;
    const HP k1 = dot(q, q) - R2 - r2, k2 = dot(q, r.d);
    SturmPoly<HP> p;
    p.degree = 4;
    p.c[4] = 1;
    p.c[3] = 4 * k2;
    p.c[2] = 2 * (k1 + 2 * (k2 * k2 + R2 * r.d.y * r.d.y));
    p.c[1] = 4 * (k2 * k1 + 2 * R2 * q.y * r.d.y);
    p.c[0] = k1 * k1 + 4 * R2 * (q.y * q.y - r2);
    HP roots[4];
    const HP far =
        sqrt(dot(r.o, r.o)) + 2 * (s.band_radius + s.bottom_radius + s.top_radius);
    const int n = sturm_real_roots(p, HP(0), far, roots, 4);
    for (int i = 0; i < n; ++i) {
        const V3 x = r.o + r.d * roots[i];
        if (!(x.y > s.band_bottom && x.y < s.band_top)) continue;
        const HP rho = sqrt(x.x * x.x + x.z * x.z);
        const HP a = rho + s.band_offset, b = x.y - s.band_height;
        // On the band, not on the torus's outer part.
        if (abs(a * a + b * b - r2) < HP(1e-20) * (1 + r2))
            best.offer(roots[i], kPovEpsilon);
    }
    return true;
}

}  // namespace povwall::trace
