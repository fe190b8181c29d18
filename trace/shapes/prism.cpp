#include "trace/shapes/prism.h"

#include <algorithm>
#include <cmath>

#include "core/math_constants.h"
#include "core/pov_polysolve.h"
#include "trace/pov_bounds.h"
#include "trace/roots_sturm.h"
#include "trace/shapes/oracle_math.h"
#include "trace/shapes/sort_hits.h"

namespace povwall::trace {
namespace {

constexpr Real kPrismDepthTolerance = 1e-4;  // prism.cpp's DEPTH_TOLERANCE

Real at(const PrismSegment& s, int axis, Real t) {
    return t * (t * (t * s.a[axis] + s.b[axis]) + s.c[axis]) + s.d[axis];
}
Real slope(const PrismSegment& s, int axis, Real t) {
    return t * (3 * s.a[axis] * t + 2 * s.b[axis]) + s.c[axis];
}

// A ray starting outside a rectangle of (x, z) and moving away from it.
bool leaves_rectangle(Real x1, Real x2, Real y1, Real y2, const Point3& P,
                      const Vector3& D) {
    return (D.x >= 0 && P.x > x2) || (D.x <= 0 && P.x < x1) || (D.z >= 0 && P.z > y2) ||
           (D.z <= 0 && P.z < y1);
}

// The 2-D slab test of the ray's (x, z) projection against a segment's rectangle, done
// before a cubic is solved (POV-Ray's test_rectangle).
bool meets_rectangle(const PrismSegment& s, const Point3& P, const Vector3& D) {
    Real x0 = -kBoundHuge, x1 = kBoundHuge;
    if (std::fabs(D.x) > kPovEpsilon) {
        x0 = (s.x1 - P.x) / D.x;
        x1 = (s.x2 - P.x) / D.x;
        if (x0 > x1) std::swap(x0, x1);
        if (x1 < kPovEpsilon) return false;
    } else if (P.x < s.x1 || P.x > s.x2) {
        return false;
    }
    if (std::fabs(D.z) > kPovEpsilon) {
        Real z0 = (s.y1 - P.z) / D.z, z1 = (s.y2 - P.z) / D.z;
        if (z0 > z1) std::swap(z0, z1);
        if (z1 < x1 && z1 < kPovEpsilon) return false;
        if (z0 > x1 || x0 > z1) return false;
    } else if (P.z < s.y1 || P.z > s.y2) {
        return false;
    }
    return true;
}

// The wall equation's roots in t: degree 1, 2 or 3 by the spline.
int wall_roots(const Prism& p, const Real c[4], Real roots[3]) {
    switch (p.spline) {
        case Prism::Spline::Linear:
            if (std::fabs(c[2]) > kPovEpsilon) {
                roots[0] = -c[3] / c[2];
                return 1;
            }
            return 0;
        case Prism::Spline::Quadratic:
            return pov_solve_polynomial(2, c + 1, roots, false);
        case Prism::Spline::Cubic:
        case Prism::Spline::Bezier:
            return pov_solve_polynomial(3, c, roots, p.sturm, 0,
                                        1.0);  // t in [0, 1] kept
    }
    return 0;
}

// The crossings of segment j's wall, in POV-Ray's order: push(k, j, t) for each at
// object depth k whose height lies between the prism's (k1..k3: the conic sweep's plane
// through the apex and the ray).
template <class Push>
void wall_hits(const Prism& p, const PrismSegment& s, int j, const Point3& P,
               const Vector3& D, Real k1, Real k2, Real k3, Push&& push) {
    Real c[4];
    if (!p.conic) {
        // Where the ray's (x, z) line crosses the curve: D.z (u - Px) = D.x (v - Pz).
        c[0] = s.a[0] * D.z - s.a[1] * D.x;
        c[1] = s.b[0] * D.z - s.b[1] * D.x;
        c[2] = s.c[0] * D.z - s.c[1] * D.x;
        c[3] = D.z * (s.d[0] - P.x) - D.x * (s.d[1] - P.z);
        const bool cubic =
            p.spline == Prism::Spline::Cubic || p.spline == Prism::Spline::Bezier;
        if (cubic && !meets_rectangle(s, P, D)) return;
    } else {
        // Where the plane through the apex and the ray crosses the curve at y = 1.
        c[0] = s.a[0] * k1 + s.a[1] * k2;
        c[1] = s.b[0] * k1 + s.b[1] * k2;
        c[2] = s.c[0] * k1 + s.c[1] * k2;
        c[3] = s.d[0] * k1 + s.d[1] * k2 + k3;
    }
    Real roots[3];
    const int n = wall_roots(p, c, roots);
    for (int i = n - 1; i >= 0; --i) {
        const Real t = roots[i];
        if (!(t >= 0 && t <= 1)) continue;
        Real k;
        if (!p.conic) {
            k = std::fabs(D.x) > kPovEpsilon ? (at(s, 0, t) - P.x) / D.x
                                             : (at(s, 1, t) - P.z) / D.z;
        } else {
            const Real U = at(s, 0, t);
            Real h = D.x - U * D.y;
            if (std::fabs(h) > kPovEpsilon) {
                k = (U * P.y - P.x) / h;
            } else {
                const Real V = at(s, 1, t);
                h = D.z - V * D.y;
                if (!(std::fabs(h) > kPovEpsilon)) continue;
                k = (V * P.y - P.z) / h;
            }
        }
        const Real y = P.y + k * D.y;
        if (y >= p.height1 && y <= p.height2) push(k, j, t);
    }
}

}  // namespace

bool prism_in_curve(const Prism& p, Real u, Real v) {
    if (u < p.u1 || u > p.u2 || v < p.v1 || v > p.v2) return false;
    int crossings = 0;
    for (const PrismSegment& s : p.segments) {
        if (v < s.v1 || v > s.v2 || u > s.u2) continue;
        const Real c[4] = {s.a[1], s.b[1], s.c[1], s.d[1] - v};
        Real roots[3];
        const int n = pov_solve_polynomial(3, c, roots, p.sturm, 0, 1.0);
        for (int i = 0; i < n; ++i) {
            const Real t = roots[i];
            if (t >= 0 && t <= 1 && at(s, 0, t) - u >= 0) ++crossings;
        }
    }
    return crossings & 1;
}

void shape_hits(const Prism& p, const LocalRay& r, ShapeHits& out) {
    if (p.degenerate) return;
    const Point3& P = r.origin;
    const Vector3& D = r.unit;
    const Real len = r.length;
    if (leaves_rectangle(p.x1, p.x2, p.y1, p.y2, P, D)) return;
    const size_t first = out.size();
    // Object-space distance k along the unit direction: kept when its world distance
    // is within POV-Ray's depth range.
    auto push = [&](Real k, int face, Real s) {
        const Real w = k / len;
        if (w > kPrismDepthTolerance && w < kMaxDistance)
            out.push_back({w, P + D * k, face, s});
    };
    const Real H1 = p.height1, H2 = p.height2;
    if (std::fabs(D.y) < kPovEpsilon && (P.y < H1 || P.y > H2)) return;
    // With r.nearest_only, crossings past `cutoff` (world) are not wanted: want_hi,
    // lowered to each crossing found in [want_lo, want_hi). A wall segment or cap whose
    // crossings all lie beyond it is not solved. The walls are found first for that,
    // the caps then go before them in the list, as found in POV-Ray's order.
    Real cutoff = r.want_hi;
    auto lower_cutoff = [&](size_t from) {
        for (size_t i = from; i < out.size(); ++i)
            if (out[i].t >= r.want_lo && out[i].t < cutoff) cutoff = out[i].t;
    };
    // A margin far above the rounding of a crossing's depth (relative 1e-16 of the
    // coordinates involved) for the lower bounds below.
    const Real margin = 1e-9 * (std::fabs(P.x) + std::fabs(P.y) + std::fabs(P.z) +
                                std::fabs(H1) + std::fabs(H2) + std::fabs(p.x1) +
                                std::fabs(p.x2) + std::fabs(p.y1) + std::fabs(p.y2));
    const bool prunable = r.nearest_only && std::isfinite(margin);
    // A wall crossing lies between the heights: along a ray that is not level, its
    // object depth is at least that of the nearer height.
    Real wall_floor = -kBoundHuge;
    if (prunable && std::fabs(D.y) >= kPovEpsilon)
        wall_floor = (D.y > 0 ? H1 - P.y - margin : H2 - P.y + margin) / D.y;
    const size_t walls_at = out.size();
    // Whether a crossing from `from` on ends the search (r.any_crossing).
    bool ended_search = false;
    auto ended = [&](size_t from) {
        for (size_t i = from; i < out.size() && !ended_search; ++i)
            ended_search = r.ends_search(out[i].t);
        return ended_search;
    };
    // Walls (an exactly vertical ray in object space meets none, even conic ones).
    if (std::fabs(D.x) > kPovEpsilon || std::fabs(D.z) > kPovEpsilon) {
        const Real k1 = P.z * D.y - P.y * D.z, k2 = P.y * D.x - P.x * D.y,
                   k3 = P.x * D.z - P.z * D.x;
        for (size_t j = 0; j < p.segments.size(); ++j) {
            const PrismSegment& s = p.segments[j];
            if (leaves_rectangle(s.x1, s.x2, s.y1, s.y2, P, D)) continue;
            if (prunable) {
                // A linear sweep's wall crossing lies in the segment's rectangle, its
                // depth from x (or z) as below.
                Real floor = wall_floor;
                if (!p.conic) {
                    const Real near =
                        std::fabs(D.x) > kPovEpsilon
                            ? (D.x > 0 ? s.x1 - P.x - margin : s.x2 - P.x + margin) / D.x
                            : (D.z > 0 ? s.y1 - P.z - margin : s.y2 - P.z + margin) / D.z;
                    floor = std::max(floor, near);
                }
                if (floor / len > cutoff) continue;
            }
            const size_t found = out.size();
            wall_hits(p, s, int(j), P, D, k1, k2, k3, push);
            if (prunable) lower_cutoff(found);
            if (ended(found)) break;
        }
    }
    // The cap (height2) first, then the base; the object-space depth is checked too.
    thread_local ShapeHits walls;
    walls.assign(out.begin() + std::ptrdiff_t(walls_at), out.end());
    out.resize(walls_at);
    if (std::fabs(D.y) >= kPovEpsilon && !p.open && !ended_search) {
        for (int end = 0; end < 2 && !ended(walls_at); ++end) {
            const Real H = end == 0 ? H2 : H1;
            const int face = end == 0 ? kPrismCap : kPrismBase;
            if (p.conic && !(std::fabs(H) > kPovEpsilon)) continue;
            const Real k = (H - P.y) / D.y;
            if (!(k > kPrismDepthTolerance && k < kMaxDistance)) continue;
            if (prunable && k / len > cutoff) continue;
            Real u = P.x + k * D.x, v = P.z + k * D.z;
            if (p.conic) {
                u /= H;
                v /= H;
            }
            if (prism_in_curve(p, u, v)) push(k, face, 0);
        }
    }
    out.insert(out.end(), walls.begin(), walls.end());
    stable_sort_by_depth(out, first);
}

Vector3 shape_normal(const Prism& p, const ShapeHit& h) {
    // Base and cap alike: +y (the tracer faces normals towards the ray).
    if (h.face < 0) return {0, 1, 0};
    const PrismSegment& s = p.segments[size_t(h.face)];
    const Real du = slope(s, 0, h.param), dv = slope(s, 1, h.param);
    if (!p.conic) return {dv, 0, -du};
    if (!(std::fabs(h.p.y) > kPovEpsilon)) return {0, 1, 0};
    return {dv, -(h.p.x * dv - h.p.z * du) / h.p.y, -du};
}

bool shape_inside(const Prism& p, const Point3& q) {
    // The top is open: y = height2 is outside.
    if (!(q.y >= p.height1 && q.y < p.height2)) return false;
    if (!p.conic) return prism_in_curve(p, q.x, q.z);
    if (!(std::fabs(q.y) > kPovEpsilon)) return false;
    return prism_in_curve(p, q.x / q.y, q.z / q.y);
}

Bounds3 shape_bounds(const Prism& p) {
    return {{p.x1, p.height1, p.y1}, {p.x2, p.height2, p.y2}};
}

PovBBox shape_pov_bbox(const Prism& p, const CompactTransform& xf) {
    return pov_transformed_bbox(shape_bounds(p), xf);
}

bool shape_oracle_first(const Prism& p, const OracleRay& r, OracleBest& best) {
    if (p.degenerate) return true;
    const HP H1 = p.height1, H2 = p.height2;
    // Caps: the plane crossing, inside the curves (the even-odd test in double at the
    // 50-digit point: it decides containment, not depth).
    if (!p.open && r.d.y != 0) {
        for (const HP& H : {H2, H1}) {
            if (p.conic && H == 0) continue;
            const HP k = (H - r.o.y) / r.d.y;
            HP u = r.o.x + k * r.d.x, v = r.o.z + k * r.d.z;
            if (p.conic) {
                u /= H;
                v /= H;
            }
            if (prism_in_curve(p, static_cast<Real>(u), static_cast<Real>(v)))
                best.offer(k, kPrismDepthTolerance);
        }
    }
    // Walls: the same equations in 50 digits, roots isolated by Sturm sequences.
    const HP k1 = r.o.z * r.d.y - r.o.y * r.d.z, k2 = r.o.y * r.d.x - r.o.x * r.d.y,
             k3 = r.o.x * r.d.z - r.o.z * r.d.x;
    for (const PrismSegment& s : p.segments) {
        HP c[4];
        for (int i = 0; i < 3; ++i) {
            const Real cu = i == 0 ? s.a[0] : i == 1 ? s.b[0] : s.c[0];
            const Real cv = i == 0 ? s.a[1] : i == 1 ? s.b[1] : s.c[1];
            c[i] = p.conic ? HP(cu) * k1 + HP(cv) * k2 : HP(cu) * r.d.z - HP(cv) * r.d.x;
        }
        c[3] = p.conic ? HP(s.d[0]) * k1 + HP(s.d[1]) * k2 + k3
                       : r.d.z * (HP(s.d[0]) - r.o.x) - r.d.x * (HP(s.d[1]) - r.o.z);
        SturmPoly<HP> poly;
        poly.degree = 3;
        while (poly.degree > 0 && c[3 - poly.degree] == 0) --poly.degree;
        if (poly.degree == 0) continue;
        for (int i = 0; i <= poly.degree; ++i) poly.c[i] = c[3 - i];
        HP roots[3];
        const int n = sturm_real_roots(poly, HP(-1e-30), HP(1) + HP(1e-30), roots, 3);
        for (int i = 0; i < n; ++i) {
            const HP& t = roots[i];
            const HP U = ((HP(s.a[0]) * t + s.b[0]) * t + s.c[0]) * t + s.d[0];
            const HP V = ((HP(s.a[1]) * t + s.b[1]) * t + s.c[1]) * t + s.d[1];
            HP k;
            if (!p.conic) {
                k = abs(r.d.x) > abs(r.d.z) ? (U - r.o.x) / r.d.x : (V - r.o.z) / r.d.z;
            } else {
                const HP hx = r.d.x - U * r.d.y, hz = r.d.z - V * r.d.y;
                if (hx == 0 && hz == 0) continue;
                k = abs(hx) > abs(hz) ? (U * r.o.y - r.o.x) / hx
                                      : (V * r.o.y - r.o.z) / hz;
            }
            const HP y = r.o.y + k * r.d.y;
            if (y >= H1 && y <= H2) best.offer(k, kPrismDepthTolerance);
        }
    }
    return true;
}

}  // namespace povwall::trace
