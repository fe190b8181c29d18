#include "trace/shapes/sphere_sweep.h"

#include <algorithm>
#include <cmath>

#include "core/math_constants.h"
#include "core/pov_polysolve.h"
#include "trace/roots_sturm.h"
#include "trace/shapes/oracle_math.h"

namespace povwall::trace {
namespace {

constexpr Real kSphereSweepZeroTolerance = 1e-4;  // sphsweep.cpp's ZERO_TOLERANCE
constexpr Real kRootElimination = 1e-10;          // the eps its solver calls pass

Real sqr(Real x) { return x * x; }

bool in_range(Real t) { return t > -kMaxDistance && t < kMaxDistance; }

// The line's two crossings of a sphere (POV-Ray's Intersect_Sphere): none when the
// sphere lies behind an origin outside it, or the chord is too short. The normal is
// divided by the signed radius (a negative radius points it inwards).
bool sphere_crossings(const Point3& o, const Vector3& d, const Point3& centre,
                      Real radius, SweepCrossing out[2]) {
    const Real r2 = sqr(radius);
    const Vector3 oc = centre - o;
    const Real oc2 = dot(oc, oc);
    const Real closest = dot(oc, d);
    if (oc2 >= r2 && closest < kPovEpsilon) return false;
    const Real half2 = r2 - oc2 + sqr(closest);
    if (!(half2 > kPovEpsilon)) return false;
    const Real half = std::sqrt(half2);
    const Real inv_radius = 1.0 / radius;
    for (int i = 0; i < 2; ++i) {
        SweepCrossing& c = out[i];
        c.t = i == 0 ? closest - half : closest + half;
        c.p = o + d * c.t;
        c.normal = (c.p - centre) * inv_radius;
    }
    return true;
}

// The plane of the circle where the segment's end sphere touches the envelope, inside
// that sphere (the end cap of segment end 0 or 1).
void cap_crossing(const SweepSegment& s, int end, const Point3& o, const Vector3& d,
                  std::vector<SweepCrossing>& out) {
    const Vector3& axis = s.centre_deriv[end];
    const Real along = dot(d, axis);
    if (!(std::fabs(along) > kPovEpsilon)) return;
    const SweepSphere& sphere = s.closing[end];
    const Real t =
        -(dot(o - sphere.centre, axis) + sphere.radius * s.radius_deriv[end]) / along;
    if (!in_range(t)) return;
    const Point3 p = o + d * t;
    const Vector3 off = p - sphere.centre;
    if (!(dot(off, off) < sqr(sphere.radius))) return;
    out.push_back({t, p, normalize(end == 0 ? axis * -1.0 : axis)});
}

// The envelope of a linear segment: F(t, u) = t^2 + t (b u + c) + d u^2 + e u + f = 0
// with dF/du = 0, a quadratic in u.
void linear_tube(const SweepSegment& s, const Point3& o, const Vector3& d,
                 std::vector<SweepCrossing>& out) {
    const Vector3& c1 = s.centre_coef[1];
    const Real r0 = s.radius_coef[0], r1 = s.radius_coef[1];
    const Vector3 v = o - s.centre_coef[0];
    const Real b = dot(c1, d) * -2.0;
    const Real c = dot(v, d) * 2.0;
    const Real dd = dot(c1, c1) - sqr(r1);
    const Real e = (dot(v, c1) + r0 * r1) * -2.0;
    const Real f = dot(v, v) - sqr(r0);
    const Real coef[3] = {4.0 * sqr(dd) - sqr(b) * dd, 4.0 * dd * e - 2.0 * b * c * dd,
                          sqr(e) - b * c * e + sqr(b) * f};
    Real roots[2];
    const int n = pov_solve_polynomial(2, coef, roots, true, kRootElimination);
    for (int i = 0; i < n; ++i) {
        const Real u = roots[i];
        if (u < 0.0 || u > 1.0) continue;
        const Point3 centre = s.centre_coef[0] + c1 * u;
        if (std::fabs(b) > kSphereSweepZeroTolerance) {
            const Real t = -(2.0 * dd * u + e) / b;
            if (!in_range(t)) continue;
            const Point3 p = o + d * t;
            out.push_back({t, p, normalize(p - centre)});
        } else {
            // The ray crosses the axis at a right angle: the sphere at u itself.
            SweepCrossing two[2];
            if (sphere_crossings(o, d, centre, r1 * u + r0, two)) {
                out.push_back(two[0]);
                out.push_back(two[1]);
            }
        }
    }
}

// The envelope of a cubic segment: with F(t, u) = t^2 + t E(u) + G(u), E cubic and G
// of degree 6, eliminating t from F = dF/du = 0 gives G'^2 - G' E' E + E'^2 G = 0 of
// degree 10. Each root's sphere is met as a whole (POV-Ray 3.7 leaves out the direct
// t = -G'/E', FS#81): both its crossings go in, the cull drops the inner one.
void cubic_tube(const SweepSegment& s, const Point3& o, const Vector3& dir,
                std::vector<SweepCrossing>& out) {
    const Vector3* C = s.centre_coef;
    const Real* R = s.radius_coef;
    const Vector3 v = o - C[0];
    const Real b = dot(C[3], dir) * -2.0;
    const Real c = dot(C[2], dir) * -2.0;
    const Real d = dot(C[1], dir) * -2.0;
    const Real e = dot(v, dir) * 2.0;
    const Real f = dot(C[3], C[3]) - sqr(R[3]);
    const Real g = (dot(C[3], C[2]) - R[3] * R[2]) * 2.0;
    Real h = dot(C[3], C[1]) * 2.0;
    h += dot(C[2], C[2]);
    h -= 2.0 * R[3] * R[1];
    h -= sqr(R[2]);
    Real i = dot(C[3], v);
    i -= dot(C[2], C[1]);
    i += R[3] * R[0];
    i += R[2] * R[1];
    i *= -2.0;
    Real j = (dot(C[2], v) + R[2] * R[0]) * -2.0;
    j += dot(C[1], C[1]);
    j -= sqr(R[1]);
    const Real k = (dot(C[1], v) + R[1] * R[0]) * -2.0;
    const Real l = dot(v, v) - sqr(R[0]);
    // Expanded in POV-Ray's order of terms (its last bits decide grazing roots).
    const Real coef[11] = {
        36.0 * sqr(f) - 9.0 * f * sqr(b),
        60.0 * f * g - 6.0 * g * sqr(b) - 18.0 * b * c * f,
        48.0 * f * h + 25.0 * sqr(g) - 3.0 * h * sqr(b) - 13.0 * b * c * g -
            8.0 * f * sqr(c) - 18.0 * b * d * f,
        36.0 * f * i + 40.0 * g * h - 18.0 * b * f * e - 8.0 * b * c * h -
            6.0 * g * sqr(c) - 14.0 * b * d * g - 14.0 * c * d * f,
        24.0 * f * j + 30.0 * g * i + 16.0 * sqr(h) - 15.0 * b * g * e -
            12.0 * c * f * e + 3.0 * j * sqr(b) - 3.0 * b * c * i - 4.0 * h * sqr(c) -
            10.0 * b * d * h - 11.0 * c * d * g - 5.0 * f * sqr(d),
        12.0 * f * k + 20.0 * g * j + 24.0 * h * i - 12.0 * b * h * e - 10.0 * c * g * e -
            6.0 * d * f * e + 6.0 * k * sqr(b) + 2.0 * b * c * j - 2.0 * i * sqr(c) -
            6.0 * b * d * i - 8.0 * c * d * h - 4.0 * g * sqr(d),
        10.0 * g * k + 16.0 * h * j + 9.0 * sqr(i) - 9.0 * b * i * e - 8.0 * c * h * e -
            5.0 * d * g * e + 9.0 * l * sqr(b) + 7.0 * b * c * k - 2.0 * b * d * j -
            5.0 * c * d * i - 3.0 * h * sqr(d),
        8.0 * h * k + 12.0 * i * j - 6.0 * b * j * e - 6.0 * c * i * e - 4.0 * d * h * e +
            12.0 * b * c * l + 2.0 * k * sqr(c) + 2.0 * b * d * k - 2.0 * c * d * j -
            2.0 * i * sqr(d),
        6.0 * i * k + 4.0 * sqr(j) - 3.0 * b * k * e - 4.0 * c * j * e - 3.0 * d * i * e +
            4.0 * l * sqr(c) + 6.0 * b * d * l + c * d * k - j * sqr(d),
        4.0 * j * k - 2.0 * c * k * e - 2.0 * d * j * e + 4.0 * c * d * l,
        sqr(k) - d * k * e + l * sqr(d)};
    Real roots[10];
    const int n = sweep_bezier_roots(10, coef, roots);
    for (int m = 0; m < n; ++m) {
        const Real u = roots[m];
        if (u < 0.0 || u > 1.0) continue;
        const Point3 centre = C[0] + C[1] * u + C[2] * (u * u) + C[3] * (u * u * u);
        const Real radius = R[3] * u * u * u + R[2] * u * u + R[1] * u + R[0];
        SweepCrossing two[2];
        if (sphere_crossings(o, dir, centre, radius, two)) {
            out.push_back(two[0]);
            out.push_back(two[1]);
        }
    }
}

// POV-Ray's Find_Valid_Points: the first crossing is taken as an entry and kept, as is
// the last; in between, a crossing is kept when it enters from outside every part or
// leaves the last part the line was in (by the sign of normal . dir).
void cull_inner(std::vector<SweepCrossing>& list, const Vector3& dir) {
    int inside = 1;
    size_t w = 1;
    const size_t n = list.size();
    if (n < 3) return;
    for (size_t i = 1; i + 1 < n; ++i) {
        bool keep;
        if (dot(list[i].normal, dir) < 0.0) {
            keep = inside == 0;
            ++inside;
        } else {
            keep = inside == 1;
            --inside;
        }
        if (keep) list[w++] = list[i];
    }
    list[w++] = list[n - 1];
    list.resize(w);
}

// A segment's distance polynomial at p: |p - C(u)|^2 - r(u)^2, highest power first.
int distance_roots(const SweepSegment& s, const Point3& p, Real* roots) {
    const Vector3* C = s.centre_coef;
    const Real* R = s.radius_coef;
    const Vector3 v = p - C[0];
    if (s.coefficients == 2) {
        const Real coef[3] = {dot(C[1], C[1]) - sqr(R[1]),
                              (dot(v, C[1]) + R[0] * R[1]) * -2.0, dot(v, v) - sqr(R[0])};
        return pov_solve_polynomial(2, coef, roots, true, kRootElimination);
    }
    Real coef[7];
    coef[0] = dot(C[3], C[3]) - sqr(R[3]);
    coef[1] = (dot(C[3], C[2]) - R[3] * R[2]) * 2.0;
    coef[2] = dot(C[3], C[1]) * 2.0;
    coef[2] += dot(C[2], C[2]);
    coef[2] -= 2.0 * R[3] * R[1];
    coef[2] -= sqr(R[2]);
    coef[3] = dot(C[3], v);
    coef[3] -= dot(C[2], C[1]);
    coef[3] += R[3] * R[0];
    coef[3] += R[2] * R[1];
    coef[3] *= -2.0;
    coef[4] = (dot(C[2], v) + R[2] * R[0]) * -2.0;
    coef[4] += dot(C[1], C[1]);
    coef[4] -= sqr(R[1]);
    coef[5] = (dot(C[1], v) + R[1] * R[0]) * -2.0;
    coef[6] = dot(v, v) - sqr(R[0]);
    return sweep_bezier_roots(6, coef, roots);
}

}  // namespace

int sweep_bezier_roots(int degree, const Real* c, Real* roots) {
    // The common multiples turning power coefficients into Bernstein ones on [0, 1],
    // before the running sums.
    static constexpr Real kScale6[7] = {60, 10, 4, 3, 4, 10, 60};
    static constexpr Real kScale10[11] = {2520, 252, 56, 21,  12,  10,
                                          12,   21,  56, 252, 2520};
    const Real* scale = degree == 6 ? kScale6 : kScale10;
    Real b[11];
    for (int i = 0; i <= degree; ++i) b[i] = c[i] * scale[i];
    bool non_negative = true, non_positive = true;
    for (int i = 0; i <= degree; ++i) {
        non_negative = non_negative && b[degree - i] >= 0;
        non_positive = non_positive && b[degree - i] <= 0;
        if (!(non_negative || non_positive))
            return pov_solve_polynomial(degree, c, roots, true, kRootElimination);
        for (int j = 0; j < degree - i; ++j) b[j] += b[j + 1];
    }
    return 0;
}

void sweep_crossings(const SphereSweepData& s, const Point3& o, const Vector3& dir,
                     std::vector<SweepCrossing>& out) {
    out.clear();
    // POV-Ray's list holds this many; a part whose crossings do not fit is dropped whole.
    const size_t capacity = (s.joints.size() + s.segments.size()) * 2 + 64;
    for (const SweepSphere& j : s.joints) {
        SweepCrossing two[2];
        if (!sphere_crossings(o, dir, j.centre, j.radius, two)) continue;
        if (out.size() + 2 > capacity) continue;
        for (const SweepCrossing& c : two) {
            if (in_range(c.t)) out.push_back(c);
        }
    }
    thread_local std::vector<SweepCrossing> part;
    for (const SweepSegment& seg : s.segments) {
        part.clear();
        cap_crossing(seg, 0, o, dir, part);
        cap_crossing(seg, 1, o, dir, part);
        if (seg.coefficients == 2)
            linear_tube(seg, o, dir, part);
        else
            cubic_tube(seg, o, dir, part);
        if (out.size() + part.size() > capacity) continue;
        out.insert(out.end(), part.begin(), part.end());
    }
    if (out.empty()) return;
    // glibc's qsort, which POV-Ray calls, is a merge sort: stable.
    std::stable_sort(
        out.begin(), out.end(),
        [](const SweepCrossing& a, const SweepCrossing& b) { return a.t < b.t; });
    cull_inner(out, dir);
}

void shape_hits(const SphereSweep& s, const LocalRay& r, ShapeHits& out) {
    // Without a matrix POV-Ray meets the world ray as it comes (no renormalising, no
    // division); with one, the unit object direction, distances divided by its length.
    const Vector3& dir = s.has_matrix ? r.unit : r.direction;
    thread_local std::vector<SweepCrossing> list;
    sweep_crossings(*s.data, r.origin, dir, list);
    for (const SweepCrossing& c : list) {
        const Real t = s.has_matrix ? c.t / r.length : c.t;
        if (!(t > s.tolerance)) continue;
        ShapeHit h{t, c.p, 0};
        h.normal = c.normal;
        // POV-Ray maps its object-space point forward rather than following the ray.
        h.own_point = s.has_matrix;
        out.push_back(h);
    }
}

Vector3 shape_normal(const SphereSweep&, const ShapeHit& h) { return h.normal; }

bool shape_inside(const SphereSweep& s, const Point3& p) {
    // Inside where some segment's distance polynomial has a root in [0, 1] (POV-Ray's
    // test: a point deep inside a short fat segment, negative all along, is outside).
    for (const SweepSegment& seg : s.data->segments) {
        Real roots[6];
        const int n = distance_roots(seg, p, roots);
        for (int i = 0; i < n; ++i) {
            if (roots[i] >= 0.0 && roots[i] <= 1.0) return true;
        }
    }
    return false;
}

Bounds3 shape_bounds(const SphereSweep& s) {
    // Each segment's centre curve lies in the hull of its Bezier control points, its
    // radius within the largest of them in magnitude.
    Bounds3 b;
    for (const SweepSegment& seg : s.data->segments) {
        const Vector3* C = seg.centre_coef;
        const Real* R = seg.radius_coef;
        Point3 ctrl[4];
        Real rad[4];
        int n;
        if (seg.coefficients == 2) {
            n = 2;
            ctrl[0] = C[0];
            ctrl[1] = C[0] + C[1];
            rad[0] = R[0];
            rad[1] = R[0] + R[1];
        } else {
            n = 4;
            ctrl[0] = C[0];
            ctrl[1] = C[0] + C[1] / 3;
            ctrl[2] = C[0] + C[1] * (2.0 / 3) + C[2] / 3;
            ctrl[3] = C[0] + C[1] + C[2] + C[3];
            rad[0] = R[0];
            rad[1] = R[0] + R[1] / 3;
            rad[2] = R[0] + R[1] * (2.0 / 3) + R[2] / 3;
            rad[3] = R[0] + R[1] + R[2] + R[3];
        }
        Real reach = 0, size = 0;
        for (int i = 0; i < n; ++i) {
            reach = std::max(reach, std::fabs(rad[i]));
            size = std::max(
                {size, std::fabs(ctrl[i].x), std::fabs(ctrl[i].y), std::fabs(ctrl[i].z)});
        }
        // Rounding of the hull and of the crossings' arithmetic.
        reach += (size + reach) * 1e-9;
        for (int i = 0; i < n; ++i) {
            b.extend(ctrl[i] - Vector3{reach, reach, reach});
            b.extend(ctrl[i] + Vector3{reach, reach, reach});
        }
    }
    return b;
}

PovBBox shape_pov_bbox(const SphereSweep& s, const CompactTransform& xf) {
    // The modeling spheres' box (twice their radii for Catmull-Rom), single precision,
    // then through the matrix if the sweep keeps one. Negative radii invert it.
    const bool wide = s.data->spline == SweepSpline::CatmullRom;
    Bounds3 box{{kBoundHuge, kBoundHuge, kBoundHuge},
                {-kBoundHuge, -kBoundHuge, -kBoundHuge}};
    for (const SweepSphere& m : s.data->modeling) {
        const Real r = wide ? 2 * m.radius : m.radius;
        for (int a = 0; a < 3; ++a) {
            box.lo[a] = std::min(box.lo[a], m.centre[a] - r);
            box.hi[a] = std::max(box.hi[a], m.centre[a] + r);
        }
    }
    const PovBBox own = pov_bbox(box);
    if (!s.has_matrix) return own;
    return pov_bbox(pov_corners_bounds(pov_bbox_bounds(own),
                                       [&](const Point3& p) { return xf.point(p); }));
}

bool shape_oracle_first(const SphereSweep& s, const OracleRay& r, OracleBest& best) {
    // The sweep is the union of the spheres S(u) over every segment's u in [0, 1]. For a
    // ray from outside, its first crossing is the least entry into any S(u): at a joint
    // sphere or where the entry depth is stationary in u, a root of the envelope
    // condition G'^2 - G' E' E + E'^2 G (the 50-digit polynomials built here, solved by
    // Sturm sequences). Every offered entry lies at or beyond the true one.
    const Real tol = static_cast<Real>(HP(s.tolerance) / r.world_per_object);
    auto offer_sphere = [&](const V3& centre, const HP& radius) {
        const V3 oc = centre - r.o;
        const HP closest = dot(oc, r.d);
        const HP disc = radius * radius - dot(oc, oc) + closest * closest;
        if (disc > 0) best.offer(closest - sqrt(disc), tol);
    };
    for (const SweepSphere& j : s.data->joints) offer_sphere(V3(j.centre), HP(j.radius));
    using Poly = SturmPoly<HP, 10>;
    auto mul = [](const Poly& a, const Poly& b) {
        Poly m;
        m.degree = a.degree + b.degree;
        for (int i = 0; i <= m.degree; ++i) m.c[i] = 0;
        for (int i = 0; i <= a.degree; ++i)
            for (int k = 0; k <= b.degree; ++k) m.c[i + k] += a.c[i] * b.c[k];
        return m;
    };
    auto derivative = [](const Poly& a) {
        Poly d;
        d.degree = std::max(a.degree - 1, 0);
        d.c[0] = 0;
        for (int i = 1; i <= a.degree; ++i) d.c[i - 1] = HP(i) * a.c[i];
        return d;
    };
    for (const SweepSegment& seg : s.data->segments) {
        const int deg = seg.coefficients - 1;
        // Per axis w = C_w(u) - o_w, and the radius.
        Poly w[3], rad;
        for (int a = 0; a < 3; ++a) {
            w[a].degree = deg;
            for (int k = 0; k <= deg; ++k) w[a].c[k] = HP(seg.centre_coef[k][a]);
            w[a].c[0] -= r.o[a];
        }
        rad.degree = deg;
        for (int k = 0; k <= deg; ++k) rad.c[k] = HP(seg.radius_coef[k]);
        // |o + t d - C|^2 - r^2 = t^2 + t E + G: E = -2 d . w, G = w . w - r^2.
        Poly E, G = mul(rad, rad);
        E.degree = deg;
        for (int k = 0; k <= deg; ++k)
            E.c[k] = -2 * (r.d.x * w[0].c[k] + r.d.y * w[1].c[k] + r.d.z * w[2].c[k]);
        for (int k = 0; k <= G.degree; ++k) G.c[k] = -G.c[k];
        for (int a = 0; a < 3; ++a) {
            const Poly sq = mul(w[a], w[a]);
            for (int k = 0; k <= sq.degree; ++k) G.c[k] += sq.c[k];
        }
        const Poly dE = derivative(E), dG = derivative(G);
        const Poly t1 = mul(dG, dG), t2 = mul(mul(dG, dE), E), t3 = mul(mul(dE, dE), G);
        Poly env;
        env.degree = std::max({t1.degree, t2.degree, t3.degree});
        for (int k = 0; k <= env.degree; ++k) {
            env.c[k] = (k <= t1.degree ? t1.c[k] : HP(0)) -
                       (k <= t2.degree ? t2.c[k] : HP(0)) +
                       (k <= t3.degree ? t3.c[k] : HP(0));
        }
        while (env.degree > 0 && env.c[env.degree] == 0) --env.degree;
        HP roots[10];
        const int n = sturm_real_roots(env, HP(0), HP(1), roots, 10);
        for (int i = 0; i < n; ++i) {
            const HP& u = roots[i];
            HP radius = 0;
            HP centre_c[3] = {0, 0, 0};
            for (int k = deg; k >= 0; --k) {
                radius = radius * u + seg.radius_coef[k];
                for (int a = 0; a < 3; ++a)
                    centre_c[a] = centre_c[a] * u + seg.centre_coef[k][a];
            }
            offer_sphere(V3(centre_c[0], centre_c[1], centre_c[2]), radius);
        }
    }
    return true;
}

}  // namespace povwall::trace
