#include "trace/shapes/sor.h"

#include <algorithm>
#include <cmath>

#include "core/pov_polysolve.h"
#include "trace/roots_sturm.h"
#include "trace/shapes/bounding_cylinders.h"
#include "trace/shapes/oracle_math.h"

namespace povwall::trace {

namespace {

constexpr Real kCapTolerance = 1e-4;  // caps narrower than 0.01 are never hit

// The cubic in the ray distance k whose roots are the crossings of segment `e`:
// r^2(Py + k Dy) = |P_xz + k D_xz|^2, highest power first.
void segment_cubic(const SorSpline::Segment& e, const Point3& p, const Vector3& d, Real a,
                   Real c[4]) {
    c[0] = e.a * d.y * d.y * d.y;
    c[1] = d.y * d.y * (3.0 * e.a * p.y + e.b) - a;
    c[2] =
        d.y * (p.y * (3.0 * e.a * p.y + 2.0 * e.b) + e.c) - 2.0 * (p.x * d.x + p.z * d.z);
    c[3] = p.y * (p.y * (e.a * p.y + e.b) + e.c) + e.d - p.x * p.x - p.z * p.z;
}

}  // namespace

void intersect_sor(const Sor& s, const Point3& p, const Vector3& d, Real dir_length,
                   ShapeHits& out) {
    const SorSpline& sp = *s.spline;
    if ((d.y >= 0 && p.y > sp.height2) || (d.y <= 0 && p.y < sp.height1) ||
        (d.x >= 0 && p.x > sp.radius2) || (d.x <= 0 && p.x < -sp.radius2))
        return;
    // The ray's signed distance from the axis: POV-Ray rejects one side only.
    Real r0 = p.x * d.z - p.z * d.x;
    const Real a = d.x * d.x + d.z * d.z;
    if (a > 0) r0 /= std::sqrt(a);
    if (r0 > sp.radius2) return;
    auto push = [&](Real k, int face) {
        const Real t = k / dir_length;
        if (t > kMinIsectDepth && t < kMaxDistance) out.push_back({t, p + d * k, face});
    };
    if (!s.open && std::fabs(d.y) > kPovEpsilon) {
        auto cap = [&](Real height, Real radius2, int face) {
            if (!(radius2 > kCapTolerance)) return;
            const Real k = (height - p.y) / d.y;
            const Real u = p.x + k * d.x, v = p.z + k * d.z;
            if (u * u + v * v <= radius2) push(k, face);
        };
        cap(sp.height1, sp.base_radius2, kSorBase);
        cap(sp.height2, sp.cap_radius2, kSorCap);
    }
    thread_local std::vector<SegmentInterval> intervals;
    bounding_cylinder_intervals(sp.cylinders, p, d, intervals);
    for (const SegmentInterval& in : intervals) {
        const SorSpline::Segment& e = sp.segments[in.segment];
        Real c[4], roots[3];
        segment_cubic(e, p, d, a, c);
        int n = pov_solve_polynomial(3, c, roots, s.sturm);
        const BoundingCylinders::Segment& bc = sp.cylinders.segments[in.segment];
        const Real h1 = sp.cylinders.heights[bc.h1], h2 = sp.cylinders.heights[bc.h2];
        while (n--) {
            const Real h = p.y + roots[n] * d.y;
            if (h >= h1 && h <= h2) push(roots[n], int(in.segment));
        }
    }
}

Vector3 sor_normal(const Sor& s, const Point3& p, int face) {
    if (face == kSorBase) return {0, -1, 0};
    if (face == kSorCap) return {0, 1, 0};
    // Half the gradient of x^2 + z^2 - r^2(y).
    const SorSpline::Segment& e = s.spline->segments[face];
    const Real half_slope = 0.5 * (p.y * (3.0 * e.a * p.y + 2.0 * e.b) + e.c);
    return {p.x, -half_slope, p.z};
}

bool inside_sor(const Sor& s, const Point3& p) {
    // The solid of revolution, open or not: the first segment holding the height.
    const SorSpline& sp = *s.spline;
    const Real r2 = p.x * p.x + p.z * p.z;
    if (!(p.y >= sp.height1 && p.y <= sp.height2 && r2 <= sp.radius2 * sp.radius2))
        return false;
    for (size_t i = 0; i < sp.segments.size(); ++i) {
        const BoundingCylinders::Segment& bc = sp.cylinders.segments[i];
        if (!(p.y >= sp.cylinders.heights[bc.h1] && p.y <= sp.cylinders.heights[bc.h2]))
            continue;
        const SorSpline::Segment& e = sp.segments[i];
        return r2 <= p.y * (p.y * (p.y * e.a + e.b) + e.c) + e.d;
    }
    return false;
}

void shape_hits(const Sor& s, const LocalRay& r, ShapeHits& out) {
    const size_t first = out.size();
    intersect_sor(s, r.origin, r.unit, r.length, out);
    std::sort(out.begin() + first, out.end(),
              [](const ShapeHit& a, const ShapeHit& b) { return a.t < b.t; });
}

Vector3 shape_normal(const Sor& s, const ShapeHit& h) {
    return sor_normal(s, h.p, h.face);
}

bool shape_inside(const Sor& s, const Point3& p) { return inside_sor(s, p); }

Bounds3 shape_bounds(const Sor& s) {
    const SorSpline& sp = *s.spline;
    return {{-sp.radius2, sp.height1, -sp.radius2}, {sp.radius2, sp.height2, sp.radius2}};
}

PovBBox shape_pov_bbox(const Sor& s, const CompactTransform& xf) {
    return pov_transformed_bbox(shape_bounds(s), xf);
}

bool shape_oracle_first(const Sor& s, const OracleRay& r, OracleBest& best) {
    // Every segment's cubic in 50 digits (no bounding cylinders), roots by Sturm
    // isolation, kept on the segment's heights; then the caps.
    const SorSpline& sp = *s.spline;
    const HP a = r.d.x * r.d.x + r.d.z * r.d.z;
    const HP reach =
        sqrt(dot(r.o, r.o)) +
        2 * (abs(HP(sp.radius2)) + abs(HP(sp.height1)) + abs(HP(sp.height2)) + 1);
    for (size_t i = 0; i < sp.segments.size(); ++i) {
        const SorSpline::Segment& e = sp.segments[i];
        const HP A = e.a, B = e.b, C = e.c, D = e.d;
        const HP &px = r.o.x, &py = r.o.y, &pz = r.o.z, &dy = r.d.y;
        SturmPoly<HP> poly;
        poly.degree = 3;
        poly.c[3] = A * dy * dy * dy;
        poly.c[2] = dy * dy * (3 * A * py + B) - a;
        poly.c[1] = dy * (py * (3 * A * py + 2 * B) + C) - 2 * (px * r.d.x + pz * r.d.z);
        poly.c[0] = py * (py * (A * py + B) + C) + D - px * px - pz * pz;
        while (poly.degree > 0 && poly.c[poly.degree] == 0) --poly.degree;
        HP roots[3];
        const int n = sturm_real_roots(poly, HP(0), reach, roots, 3);
        const BoundingCylinders::Segment& bc = sp.cylinders.segments[i];
        for (int j = 0; j < n; ++j) {
            const HP h = py + roots[j] * dy;
            if (h >= sp.cylinders.heights[bc.h1] && h <= sp.cylinders.heights[bc.h2])
                best.offer(roots[j], 0);
        }
    }
    if (!s.open && r.d.y != 0) {
        auto cap = [&](Real height, Real radius2) {
            if (!(radius2 > kCapTolerance)) return;
            const HP k = (HP(height) - r.o.y) / r.d.y;
            const HP u = r.o.x + k * r.d.x, v = r.o.z + k * r.d.z;
            if (u * u + v * v <= radius2) best.offer(k, 0);
        };
        cap(sp.height1, sp.base_radius2);
        cap(sp.height2, sp.cap_radius2);
    }
    return true;
}

}  // namespace povwall::trace
