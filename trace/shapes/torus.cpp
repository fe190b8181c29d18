#include "trace/shapes/torus.h"

#include <algorithm>
#include <cmath>

#include "core/pov_polysolve.h"
#include "trace/roots_sturm.h"
#include "trace/shapes/oracle_math.h"

namespace povwall::trace {

bool torus_quartic(const Torus& tor, const Point3& o0, const Vector3& dir,
                   TorusQuartic& q, Real min_t) {
    const Real R = tor.major, r = tor.minor;
    const Real bound = R + r;
    const Real tc = -dot(o0, dir);
    const Real closest2 = dot(o0 + dir * tc, o0 + dir * tc);
    if (closest2 > bound * bound) return false;
    // Start from just outside the bounding sphere to keep the quartic well conditioned,
    // as POV-Ray does.
    q.shift = 0;
    if (dot(o0, o0) > (R + 2 * r) * (R + 2 * r))
        q.shift = std::max(0.0, tc - (R + 2 * r));
    const Point3 o = o0 + dir * q.shift;
    const Real R2 = R * R, r2 = r * r;
    // (|p|^2 + R^2 - r^2)^2 = 4 R^2 (x^2 + z^2): the torus lies in the xz plane around y.
    const Real dd = dot(dir, dir), od = dot(o, dir), oo = dot(o, o);
    const Real oxz = o.x * o.x + o.z * o.z, odxz = o.x * dir.x + o.z * dir.z;
    const Real dxz = dir.x * dir.x + dir.z * dir.z;
    const Real e = oo + R2 - r2;
    q.c[4] = dd * dd;
    q.c[3] = 4 * dd * od;
    q.c[2] = 2 * dd * e + 4 * od * od - 4 * R2 * dxz;
    q.c[1] = 4 * od * e - 8 * R2 * odxz;
    q.c[0] = e * e - 4 * R2 * oxz;
    // Every crossing lies inside the bounding sphere: solve only over that chord.
    const Real half_chord = std::sqrt(std::max(0.0, bound * bound - closest2));
    const Real slack = 1e-9 * (bound + std::fabs(tc));
    q.lo = std::max(min_t - q.shift, tc - q.shift - half_chord - slack);
    q.hi = tc - q.shift + half_chord + slack;
    return q.lo < q.hi;
}

namespace {

// POV-Ray's thick-cylinder pre-test of a torus (Torus::Test_Thick_Cylinder): the ray
// meets the cap planes y = +-r inside the ring R - r .. R + r, or the outer or inner
// cylinder between the caps, ahead of its origin (EPSILON < k < MAX_DISTANCE).
bool meets_thick_cylinder(const Torus& tor, const Point3& p, const Vector3& d) {
    const Real h1 = -tor.minor, h2 = tor.minor;
    const Real r1 =
        tor.major < tor.minor ? 0 : (tor.major - tor.minor) * (tor.major - tor.minor);
    const Real r2 = (tor.major + tor.minor) * (tor.major + tor.minor);
    auto ahead = [](Real k) { return k > kPovEpsilon && k < kMaxDistance; };
    if (std::fabs(d.y) < kPovEpsilon) {
        if (p.y < h1 || p.y > h2) return false;
    } else {
        for (Real h : {h2, h1}) {
            const Real k = (h - p.y) / d.y;
            const Real u = p.x + k * d.x, v = p.z + k * d.z;
            if (ahead(k) && u * u + v * v >= r1 && u * u + v * v <= r2) return true;
        }
    }
    const Real a = d.x * d.x + d.z * d.z;
    if (!(a > kPovEpsilon)) return false;
    const Real b = p.x * d.x + p.z * d.z;
    for (Real rr : {r2, r1}) {
        Real disc = b * b - a * (p.x * p.x + p.z * p.z - rr);
        if (!(disc >= 0)) continue;
        disc = std::sqrt(disc);
        for (Real k : {(-b + disc) / a, (-b - disc) / a}) {
            const Real h = p.y + k * d.y;
            if (ahead(k) && h >= h1 && h <= h2) return true;
        }
    }
    return false;
}

}  // namespace

void intersect_torus(const Torus& tor, const Point3& o, const Vector3& dir,
                     Crossings& out, Real min_t) {
    // POV-Ray's way, step for step: its thick-cylinder pre-test, the origin moved to 2r
    // outside the bounding sphere, the monic quartic there, and its own solver (closed
    // form unless `sturm`, root elimination at 1e-4). Its closed form loses roots and
    // accuracy on thin large tori (a ring of radius 1000 and tube 1 seen across: 999.995
    // for 999); POV-Ray's pixels, and its trace(), come from those roots, and so do ours.
    // A root near the moved origin is eliminated: the cubic's roots left are off the
    // surface (a torus of minor radius ~1e-4 or below), and POV-Ray shades them there.
    if (!meets_thick_cylinder(tor, o, dir)) return;
    const Real R2 = tor.major * tor.major, r2 = tor.minor * tor.minor;
    const Real bound = tor.major + 2 * tor.minor;
    Real closer = 0;
    Point3 p = o;
    const Real dist2 = dot(o, o);
    if (dist2 > bound * bound) {
        closer = std::sqrt(dist2) - bound;
        p = o + dir * closer;
    }
    const Real k1 = p.x * p.x + p.z * p.z + p.y * p.y - R2 - r2;
    const Real k2 = p.x * dir.x + p.z * dir.z + p.y * dir.y;
    const Real c[5] = {1.0, 4 * k2, 2 * (k1 + 2 * (k2 * k2 + R2 * dir.y * dir.y)),
                       4 * (k2 * k1 + 2 * R2 * p.y * dir.y),
                       k1 * k1 + 4 * R2 * (p.y * p.y - r2)};
    Real roots[4];
    const int n = pov_solve_polynomial(4, c, roots, tor.sturm, kTorusTolerance);
    Real t[4];
    int m = 0;
    for (int i = 0; i < n; ++i) {
        const Real d = roots[i] + closer;
        if (d > min_t && d < kMaxDistance) t[m++] = d;
    }
    for (int i = 1; i < m; ++i)  // ascending
        for (int j = i; j > 0 && t[j] < t[j - 1]; --j) std::swap(t[j], t[j - 1]);
    for (int i = 0; i < m; ++i) out.add(t[i], 0);
}

Vector3 torus_normal(const Torus& tor, const Point3& p) {
    Real d = std::sqrt(p.x * p.x + p.z * p.z);
    if (!(d > kPovEpsilon)) return p;  // POV-Ray: no ring point, the normal is p itself
    Point3 ring{p.x * tor.major / d, 0, p.z * tor.major / d};
    return p - ring;
}

bool inside_torus(const Torus& tor, const Point3& p) {
    Real d = std::sqrt(p.x * p.x + p.z * p.z) - tor.major;
    return p.y * p.y + d * d <=
           tor.minor * tor.minor;  // POV-Ray's: the surface is inside
}

void shape_hits(const Torus& t, const LocalRay& r, ShapeHits& out) {
    Crossings cs;
    intersect_torus(t, r.origin, r.unit, cs, kTorusTolerance * r.length);
    add_unit_crossings(cs, r, out);
}

Vector3 shape_normal(const Torus& t, const ShapeHit& h) { return torus_normal(t, h.p); }

bool shape_inside(const Torus& t, const Point3& p) { return inside_torus(t, p); }

Bounds3 shape_bounds(const Torus& s) {
    Real a = s.major + s.minor;
    // A torus this thin gets POV-Ray's root elimination from afar
    // (torus_root_elimination): its crossings are the cubic's roots, off the surface but
    // within about 1.3 (R + 2r) of the centre. Its bounds cover them, so that a black box
    // holding it sees them too.
    if (s.minor < 1e-3) return {Vector3(-2 * (a + s.minor)), Vector3(2 * (a + s.minor))};
    return {{-a, -s.minor, -a}, {a, s.minor, a}};
}

PovBBox shape_pov_bbox(const Torus& s, const CompactTransform& xf) {
    const Real a = s.major + s.minor;
    return pov_transformed_bbox({{-a, -s.minor, -a}, {a, s.minor, a}}, xf);
}

bool shape_oracle_first(const Torus& s, const OracleRay& r, OracleBest& best) {
    // (|p|^2 + R^2 - r^2)^2 = 4 R^2 (x^2 + z^2) along p = o + t d, |d| = 1.
    HP R2 = HP(s.major) * s.major, r2 = HP(s.minor) * s.minor;
    HP od = dot(r.o, r.d), oo = dot(r.o, r.o);
    HP e = oo + R2 - r2;
    HP dxz = r.d.x * r.d.x + r.d.z * r.d.z;
    HP oxz = r.o.x * r.d.x + r.o.z * r.d.z;
    HP pxz = r.o.x * r.o.x + r.o.z * r.o.z;
    SturmPoly<HP> p;
    p.degree = 4;
    p.c[4] = 1;
    p.c[3] = 4 * od;
    p.c[2] = 2 * e + 4 * od * od - 4 * R2 * dxz;
    p.c[1] = 4 * od * e - 8 * R2 * oxz;
    p.c[0] = e * e - 4 * R2 * pxz;
    HP roots[4];
    HP bound = sqrt(oo) + s.major + s.minor + 1;
    int n = sturm_real_roots(p, HP(0), bound, roots, 4);
    for (int i = 0; i < n; ++i) best.offer(roots[i], kTorusTolerance);
    return true;
}

}  // namespace povwall::trace
