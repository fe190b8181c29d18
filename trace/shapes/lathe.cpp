#include "trace/shapes/lathe.h"

#include <algorithm>
#include <cmath>

#include "core/pov_polysolve.h"
#include "trace/roots_sturm.h"
#include "trace/shapes/bounding_cylinders.h"
#include "trace/shapes/oracle_math.h"

namespace povwall::trace {

namespace {

using Seg = LatheSpline::Segment;

int degree_of(LatheSplineKind kind) {
    switch (kind) {
        case LatheSplineKind::Linear:
            return 2;
        case LatheSplineKind::Quadratic:
            return 4;
        default:
            return 6;
    }
}

// The polynomial in t whose roots are the segment's crossings: with the height offset
// dw(t) = w(t) - Py, rho dw^2 + 2 Dy m dw + Dy^2 (Px^2 + Pz^2 - r(t)^2) = 0, highest
// power first, written out as POV-Ray does (rho = Dx^2 + Dz^2, m = D.P in xz).
void segment_polynomial(LatheSplineKind kind, const Seg& e, const Point3& p,
                        const Vector3& d, Real rho, Real m, Real dy2, Real* x) {
    const Real dwp = e.dw - p.y;
    const Real t1 = 2.0 * (e.cw * (dwp * rho + d.y * m) - e.cr * e.dr * dy2);
    const Real t0 =
        dwp * (dwp * rho + 2.0 * d.y * m) + dy2 * (p.x * p.x + p.z * p.z - e.dr * e.dr);
    const Real t2 = rho * (2.0 * e.bw * dwp + e.cw * e.cw) + 2.0 * e.bw * d.y * m -
                    (2.0 * e.br * e.dr + e.cr * e.cr) * dy2;
    switch (kind) {
        case LatheSplineKind::Linear:
            x[0] = e.cw * e.cw * rho - e.cr * e.cr * dy2;
            x[1] = t1;
            x[2] = t0;
            break;
        case LatheSplineKind::Quadratic:
            x[0] = e.bw * e.bw * rho - e.br * e.br * dy2;
            x[1] = 2.0 * (e.bw * e.cw * rho - e.br * e.cr * dy2);
            x[2] = t2;
            x[3] = t1;
            x[4] = t0;
            break;
        default:
            x[0] = e.aw * e.aw * rho - e.ar * e.ar * dy2;
            x[1] = 2.0 * (e.aw * e.bw * rho - e.ar * e.br * dy2);
            x[2] = (2.0 * e.aw * e.cw + e.bw * e.bw) * rho -
                   (2.0 * e.ar * e.cr + e.br * e.br) * dy2;
            x[3] = 2.0 * ((e.aw * e.dw + e.bw * e.cw - e.aw * p.y) * rho +
                          e.aw * d.y * m - (e.ar * e.dr + e.br * e.cr) * dy2);
            x[4] = (2.0 * e.bw * dwp + e.cw * e.cw) * rho + 2.0 * e.bw * d.y * m -
                   (2.0 * e.br * e.dr + e.cr * e.cr) * dy2;
            x[5] = t1;
            x[6] = t0;
            break;
    }
}

Real radius_at(const Seg& e, Real t) { return t * (t * (t * e.ar + e.br) + e.cr) + e.dr; }
Real height_at(const Seg& e, Real t) { return t * (t * (t * e.aw + e.bw) + e.cw) + e.dw; }

}  // namespace

void intersect_lathe(const Lathe& s, const Point3& p, const Vector3& d, Real dir_length,
                     ShapeHits& out, bool nearest_only, Real want_lo, Real want_hi,
                     bool any_crossing) {
    const LatheSpline& sp = *s.spline;
    if ((d.y >= 0 && p.y > sp.height2) || (d.y <= 0 && p.y < sp.height1) ||
        (d.x >= 0 && p.x > sp.radius2) || (d.x <= 0 && p.x < -sp.radius2))
        return;
    Real r0 = std::fabs(p.x * d.z - p.z * d.x);
    const Real rho = d.x * d.x + d.z * d.z;
    if (rho > 0) r0 /= std::sqrt(rho);
    if (r0 > sp.radius2) return;
    thread_local std::vector<SegmentInterval> intervals;
    bounding_cylinder_intervals(sp.cylinders, p, d, intervals);
    if (intervals.empty()) return;
    const Real m = d.x * p.x + d.z * p.z, dy2 = d.y * d.y;
    const Real dy_world = d.y * dir_length;
    const int degree = degree_of(sp.kind);
    // The linear case is a quadratic: POV-Ray solves it in closed form, sturm or not.
    const bool sturm = s.sturm && sp.kind != LatheSplineKind::Linear;
    // Crossings past `cutoff` are not wanted: want_hi, lowered to each crossing kept in
    // the wanted range.
    Real cutoff = want_hi;
    auto push = [&](Real t_world, Real k, int segment, Real param) {
        if (t_world > kMinIsectDepth && t_world < kMaxDistance) {
            out.push_back({t_world, p + d * k, segment, param});
            if (t_world >= want_lo && t_world < cutoff) cutoff = t_world;
        }
    };
    // A root's height lies within its segment's heights h1..h2 (the bounding cylinders
    // bound the spline there), so along a ray that is not level its world distance
    // (height - Py) / Dy is at least that of the nearer height, less a margin far above
    // the rounding of the height polynomial and of this quotient. Level rays (the
    // circle's quadratic) are always solved.
    const bool prunable = nearest_only && std::fabs(d.y) > kPovEpsilon;
    const Real margin = 1e-9 * (std::fabs(sp.height1) + std::fabs(sp.height2) +
                                std::fabs(p.y) + sp.radius2);
    for (const SegmentInterval& in : intervals) {
        const Seg& e = sp.segments[in.segment];
        if (prunable) {
            const BoundingCylinders::Segment& bc = sp.cylinders.segments[in.segment];
            const Real near = d.y > 0 ? sp.cylinders.heights[bc.h1] - p.y - margin
                                      : sp.cylinders.heights[bc.h2] - p.y + margin;
            if (near / dy_world > cutoff) continue;
        }
        Real x[7], roots[6];  // degree 6 at most (cubic and Bezier segments)
        segment_polynomial(sp.kind, e, p, d, rho, m, dy2, x);
        // Only spline parameters w in [0, 1] are kept: Sturm need not search above.
        int n = pov_solve_polynomial(degree, x, roots, sturm, 0, 1.0);
        const int seg = int(in.segment);
        const size_t found = out.size();
        while (n--) {
            const Real w = roots[n];
            if (!(w >= 0.0 && w <= 1.0)) continue;
            if (std::fabs(d.y) > kPovEpsilon) {
                const Real k = height_at(e, w) - p.y;
                push(k / dy_world, k / d.y, seg, w);
            } else {
                // Level with the profile point: the ray meets a circle of radius r(w).
                const Real r = radius_at(e, w);
                const Real q[3] = {rho, 2.0 * m, p.x * p.x + p.z * p.z - r * r};
                Real ks[2];
                int n2 = pov_solve_polynomial(2, q, ks, false);
                while (n2--) push(ks[n2] / dir_length, ks[n2], seg, w);
            }
        }
        if (any_crossing) {
            for (size_t i = found; i < out.size(); ++i)
                if (out[i].t >= want_lo && out[i].t < want_hi) return;
        }
    }
}

Vector3 lathe_normal(const Lathe& s, const Point3& p, int segment, Real t) {
    const Real r2 = p.x * p.x + p.z * p.z;
    if (!(r2 > kPovEpsilon)) return {0, 1, 0};
    // Perpendicular to the profile's tangent (dr, dw) turned about the axis; its sign
    // follows the order of the points, as POV-Ray's (the tracer faces it to the ray).
    const Seg& e = s.spline->segments[segment];
    const Real r = std::sqrt(r2);
    const Real dr = t * (3.0 * e.ar * t + 2.0 * e.br) + e.cr;
    const Real dw = t * (3.0 * e.aw * t + 2.0 * e.bw) + e.cw;
    return {dw * p.x, -dr * r, dw * p.z};
}

bool inside_lathe(const Lathe& s, const Point3& p) {
    // Even-odd: the profile's crossings of the horizontal line through p outside it.
    const LatheSpline& sp = *s.spline;
    const Real r = std::sqrt(p.x * p.x + p.z * p.z);
    if (!(p.y >= sp.height1 && p.y <= sp.height2 && r >= sp.radius1 && r <= sp.radius2))
        return false;
    int crossings = 0;
    for (size_t i = 0; i < sp.segments.size(); ++i) {
        const BoundingCylinders::Segment& bc = sp.cylinders.segments[i];
        if (!(p.y >= sp.cylinders.heights[bc.h1] - kPovEpsilon &&
              p.y <= sp.cylinders.heights[bc.h2] + kPovEpsilon))
            continue;
        const Seg& e = sp.segments[i];
        const Real c[4] = {e.aw, e.bw, e.cw, e.dw - p.y};
        Real roots[3];
        int n = pov_solve_polynomial(3, c, roots, s.sturm, 0, 1.0);
        while (n--)
            if (roots[n] >= 0.0 && roots[n] <= 1.0 && radius_at(e, roots[n]) - r >= 0)
                ++crossings;
    }
    return crossings % 2 == 1;
}

void shape_hits(const Lathe& s, const LocalRay& r, ShapeHits& out) {
    const size_t first = out.size();
    intersect_lathe(s, r.origin, r.unit, r.length, out, r.nearest_only, r.want_lo,
                    r.want_hi, r.nearest_only && r.any_crossing);
    std::sort(out.begin() + first, out.end(),
              [](const ShapeHit& a, const ShapeHit& b) { return a.t < b.t; });
}

Vector3 shape_normal(const Lathe& s, const ShapeHit& h) {
    return lathe_normal(s, h.p, h.face, h.param);
}

bool shape_inside(const Lathe& s, const Point3& p) { return inside_lathe(s, p); }

Bounds3 shape_bounds(const Lathe& s) {
    // Hits lie within the largest |r| (a negative end radius turns as its magnitude).
    const LatheSpline& sp = *s.spline;
    const Real r = std::max(std::fabs(sp.radius1), std::fabs(sp.radius2));
    return {{-r, sp.height1, -r}, {r, sp.height2, r}};
}

PovBBox shape_pov_bbox(const Lathe& s, const CompactTransform& xf) {
    // POV-Ray's box uses the largest signed radius.
    const LatheSpline& sp = *s.spline;
    return pov_transformed_bbox(
        {{-sp.radius2, sp.height1, -sp.radius2}, {sp.radius2, sp.height2, sp.radius2}},
        xf);
}

bool shape_oracle_first(const Lathe& s, const OracleRay& r, OracleBest& best) {
    // Every segment's polynomial in t in 50 digits (no bounding cylinders), roots in
    // [0, 1] by Sturm isolation, each turned into the ray distance.
    const LatheSpline& sp = *s.spline;
    const HP rho = r.d.x * r.d.x + r.d.z * r.d.z;
    const HP m = r.d.x * r.o.x + r.d.z * r.o.z, dy2 = r.d.y * r.d.y;
    const HP pp = r.o.x * r.o.x + r.o.z * r.o.z;
    for (const Seg& e : sp.segments) {
        const HP ar = e.ar, br = e.br, cr = e.cr, dr = e.dr;
        const HP aw = e.aw, bw = e.bw, cw = e.cw, dw = e.dw - r.o.y;
        // rho W^2 + 2 Dy m W + Dy^2 (pp - R^2), W = w(t) - Py, R = r(t), in powers of t.
        const HP W[4] = {dw, cw, bw, aw}, R[4] = {dr, cr, br, ar};
        SturmPoly<HP> poly;
        for (int i = 0; i <= 6; ++i) poly.c[i] = 0;
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j)
                poly.c[i + j] += rho * W[i] * W[j] - dy2 * R[i] * R[j];
        for (int i = 0; i < 4; ++i) poly.c[i] += 2 * r.d.y * m * W[i];
        poly.c[0] += dy2 * pp;
        poly.degree = 6;
        while (poly.degree > 0 && poly.c[poly.degree] == 0) --poly.degree;
        HP roots[6];
        const int n = sturm_real_roots(poly, HP(-1e-30), HP(1), roots, 6);
        for (int i = 0; i < n; ++i) {
            const HP& t = roots[i];
            if (abs(r.d.y) > HP(kPovEpsilon)) {
                best.offer((((aw * t + bw) * t + cw) * t + dw) / r.d.y, 0);
            } else {
                const HP rad = ((ar * t + br) * t + cr) * t + dr;
                oracle_quadratic(rho, 2 * m, pp - rad * rad, best, 0,
                                 [](const HP&) { return true; });
            }
        }
    }
    return true;
}

}  // namespace povwall::trace
