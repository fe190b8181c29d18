#include "trace/shapes/superellipsoid.h"

#include <algorithm>
#include <cmath>

#include "trace/pov_bounds.h"
#include "trace/shapes/oracle_math.h"

namespace povwall::trace {

namespace {

// POV-Ray's constants of the search (object units, along a unit direction).
constexpr Real kSuperellipsoidDepthTolerance = 1e-4;
constexpr Real kSuperellipsoidZeroTolerance = 1e-10;
constexpr Real kSlabHalf = 1.01;  // the search box; the bounding box is +-1.0001
constexpr int kMaxIterations = 20;

// The 9 planes through the origin that cut the shape into pieces on which the function
// is unimodal along a line.
constexpr Real kCutNormals[9][3] = {{1, 1, 0},  {1, -1, 0}, {1, 0, 1},
                                    {1, 0, -1}, {0, 1, 1},  {0, 1, -1},
                                    {1, 0, 0},  {0, 1, 0},  {0, 0, 1}};

// pow, with small integral exponents multiplied out as POV-Ray does: the exact products
// decide which side of the surface a sample lies on.
Real integral_power(Real x, Real p) {
    if (std::fabs(p) < 2147483647.0 && p == std::trunc(p)) {
        switch (static_cast<int>(p)) {
            case 0:
                return 1;
            case 1:
                return x;
            case 2:
                return x * x;
            case 3:
                return x * x * x;
            case 4: {
                const Real b = x * x;
                return b * b;
            }
            case 5: {
                const Real b = x * x;
                return b * b * x;
            }
            case 6: {
                const Real b = x * x;
                return b * b * b;
            }
            default:
                break;
        }
    }
    return std::pow(x, p);
}

// (x^p + y^p)^(1/p) for x, y >= 0, scaled by the larger so that it neither overflows nor
// underflows.
Real combine(Real x, Real y, Real p) {
    Real big = x, small = y;
    if (!(x > y)) {
        if (y == 0) return 0;
        big = y;
        small = x;
    }
    Real g = 1 + integral_power(small / big, p);
    if (g != 1) g = integral_power(g, 1 / p);
    return g * big;
}

struct Exponents {
    Real xy, z;  // 2/e and 2/n
};
Exponents exponents(const Superellipsoid& s) {
    return {2 / s.east_west, 2 / s.north_south};
}

Real value(const Exponents& e, const Point3& p) {
    return combine(combine(std::fabs(p.x), std::fabs(p.y), e.xy), std::fabs(p.z), e.z) -
           1;
}

// The ray's parameter range inside the search box; false when it misses it or the box
// lies behind (exit below EPSILON).
bool search_box(const Point3& o, const Vector3& d, Real& entry, Real& exit) {
    entry = -kBoundHuge;
    exit = kBoundHuge;
    for (int axis = 0; axis < 3; ++axis) {
        const Real oa = o[axis], da = d[axis];
        if (!(std::fabs(da) > kPovEpsilon)) {
            if (oa < -kSlabHalf || oa > kSlabHalf) return false;
            continue;
        }
        Real lo = (-kSlabHalf - oa) / da, hi = (kSlabHalf - oa) / da;
        if (da < 0) std::swap(lo, hi);
        exit = std::min(exit, hi);
        if (exit < kPovEpsilon) return false;
        entry = std::max(entry, lo);
        if (entry > exit) return false;
    }
    return true;
}

// Secant and bisection between two samples of opposite signs; returns the point found.
Point3 refine_sign_change(const Exponents& e, Real v0, Point3 p0, Real v1, Point3 p1) {
    for (int i = 0; i < kMaxIterations; ++i) {
        if (std::fabs(v0) < kSuperellipsoidZeroTolerance) return p0;
        if (std::fabs(v1) < kSuperellipsoidZeroTolerance) return p1;
        const Real x = std::fabs(v0) / std::fabs(v1 - v0);
        const Point3 secant = p0 + (p1 - p0) * x;
        const Real vs = value(e, secant);
        const Point3 mid = p0 + (p1 - p0) * 0.5;
        const Real vm = value(e, mid);
        if (vs * vm < 0) {
            v0 = vs, p0 = secant;
            v1 = vm, p1 = mid;
            continue;
        }
        const bool use_secant = std::fabs(vs) < std::fabs(vm);
        const Real v2 = use_secant ? vs : vm;
        const Point3 p2 = use_secant ? secant : mid;
        if (v0 * v2 < 0)
            v1 = v2, p1 = p2;
        else
            v0 = v2, p0 = p2;
    }
    return std::fabs(v0) < std::fabs(v1) ? p0 : p1;
}

// A piece [t0, t1] whose ends have the same sign may still touch or cross the surface:
// secant steps from t0 toward a zero of the function. As POV-Ray, a sign change found on
// the way is refined from the piece's first point `p0` with the latest value `v0`.
bool probe_piece(const Exponents& e, const Point3& o, const Vector3& d, Real t0,
                 const Point3& p0, Real v0, Real t1, Real& t, Point3& q) {
    Real dt0 = t0, dt1 = t0 + 0.0001 * (t1 - t0);
    const Real max_step = t1 - t0;
    for (int i = 0; dt0 < t1 && i < kMaxIterations; ++i) {
        const Point3 p1 = o + d * dt1;
        const Real v1 = value(e, p1);
        if (v0 * v1 < 0) {
            q = refine_sign_change(e, v0, p0, v1, p1);
            t = length(q - o);
            return true;
        }
        if (std::fabs(v1) < kSuperellipsoidZeroTolerance) {
            q = p1;
            t = dt1;
            return true;
        }
        if ((v0 > 0 && v1 > v0) || (v0 < 0 && v1 < v0) || v1 == v0) return false;
        const Real step = v1 * (dt1 - dt0) / (v1 - v0);
        if (std::fabs(step) > max_step) return false;
        v0 = v1;
        dt0 = dt1;
        dt1 -= step;
    }
    return false;
}

}  // namespace

Real superellipsoid_value(const Superellipsoid& s, const Point3& p) {
    return value(exponents(s), p);
}

void intersect_superellipsoid(const Superellipsoid& s, const Point3& o, const Vector3& d,
                              Real dir_length, ShapeHits& out) {
    Real t1, t2;
    if (!search_box(o, d, t1, t2) || t2 < kSuperellipsoidDepthTolerance) return;
    t1 = std::max(t1, kSuperellipsoidDepthTolerance);
    Real dists[11];
    int n = 0;
    dists[n++] = t1;
    dists[n++] = t2;
    // The box's own planes are easily missed by rounding: the range is widened a little.
    const Real slack = kPovEpsilon * (t2 - t1);
    for (const auto& c : kCutNormals) {
        const Real den = d.x * c[0] + d.y * c[1] + d.z * c[2];
        if (std::fabs(den) < kPovEpsilon) continue;
        const Real t = -(o.x * c[0] + o.y * c[1] + o.z * c[2]) / den;
        if (t >= t1 - slack && t <= t2 + slack) dists[n++] = t;
    }
    for (int i = 1; i < n; ++i)  // at most 11: insertion sort
        for (int j = i; j > 0 && dists[j] < dists[j - 1]; --j)
            std::swap(dists[j], dists[j - 1]);
    const Exponents e = exponents(s);
    const size_t first = out.size();
    // POV-Ray's insert_hit: world depth in (1e-4, 1e7); the clip test is the tracer's.
    auto push = [&](Real t_object, const Point3& p) {
        const Real t = t_object / dir_length;
        if (!(t > kMinIsectDepth && t < kMaxDistance)) return false;
        out.push_back({t, p, 0});
        return true;
    };
    auto at = [&](Real t) { return o + d * t; };
    Point3 p0 = at(dists[0]);
    Real v0 = value(e, p0);
    if (std::fabs(v0) < kSuperellipsoidZeroTolerance) push(dists[0], p0);
    for (int i = 1; i < n; ++i) {
        const Point3 p1 = at(dists[i]);
        const Real v1 = value(e, p1);
        if (std::fabs(v1) < kSuperellipsoidZeroTolerance) {
            push(dists[i], p1);
        } else if (v0 * v1 < 0) {
            const Point3 q = refine_sign_change(e, v0, p0, v1, p1);
            const Real t = length(q - o);
            push(t, at(t));
        } else {
            Real t;
            Point3 q;
            // POV-Ray stops searching when a touching hit it found is rejected. It also
            // stops when clipped_by rejects one; the clip test is the tracer's here, so
            // a clipped superellipsoid keeps the crossings behind such a hit (a
            // tangent touch inside the clipped-away part: a pixel or so, rarely).
            if (probe_piece(e, o, d, dists[i - 1], p0, v0, dists[i], t, q) &&
                !push(t, at(t)))
                break;
        }
        v0 = v1;
        p0 = p1;
    }
    // A probe may step past its piece and find a hit beyond the next one's.
    std::sort(out.begin() + first, out.end(),
              [](const ShapeHit& a, const ShapeHit& b) { return a.t < b.t; });
}

Vector3 superellipsoid_normal(const Superellipsoid& s, const Point3& p) {
    const Exponents e = exponents(s);
    // The gradient of the function times a positive factor, using that on the surface
    // (|x|^a + |y|^a)^(b/a) = 1 - |z|^b.
    Real z_term = 0;
    Vector3 n{0, 0, 0};
    if (p.z != 0) {
        z_term = integral_power(std::fabs(p.z), e.z);
        n.z = z_term / p.z;
    }
    Real ratio;
    if (std::fabs(p.x) > std::fabs(p.y)) {
        ratio = integral_power(std::fabs(p.y / p.x), e.xy);
        n.x = (1 - z_term) / p.x;
        n.y = p.y != 0 ? (1 - z_term) * ratio / p.y : 0;
    } else if (p.y != 0) {
        ratio = integral_power(std::fabs(p.x / p.y), e.xy);
        n.x = p.x != 0 ? (1 - z_term) * ratio / p.x : 0;
        n.y = (1 - z_term) / p.y;
    } else {
        // A pole: POV-Ray scales z by an uninitialised value; the direction is +-z.
        return {0, 0, p.z < 0 ? -1.0 : 1.0};
    }
    if (n.z != 0) n.z *= 1 + ratio;
    return n;
}

void shape_hits(const Superellipsoid& s, const LocalRay& r, ShapeHits& out) {
    intersect_superellipsoid(s, r.origin, r.unit, r.length, out);
}

Vector3 shape_normal(const Superellipsoid& s, const ShapeHit& h) {
    return superellipsoid_normal(s, h.p);
}

bool shape_inside(const Superellipsoid& s, const Point3& p) {
    return superellipsoid_value(s, p) < kPovEpsilon;
}

Bounds3 shape_bounds(const Superellipsoid&) {
    // Hits come from the search box, a little larger than POV-Ray's bounding box.
    return {Vector3(-kSlabHalf), Vector3(kSlabHalf)};
}

PovBBox shape_pov_bbox(const Superellipsoid&, const CompactTransform& xf) {
    return pov_transformed_bbox({Vector3(-1.0001), Vector3(1.0001)}, xf);
}

namespace {

HP hp_combine(const HP& x, const HP& y, const HP& p) {
    const HP& big = x > y ? x : y;
    if (big == 0) return HP(0);
    const HP& small = x > y ? y : x;
    return big * pow(1 + pow(small / big, p), 1 / p);
}

HP hp_value(const HP& a, const HP& b, const V3& p) {
    return hp_combine(hp_combine(abs(p.x), abs(p.y), a), abs(p.z), b) - 1;
}

}  // namespace

bool shape_oracle_first(const Superellipsoid& s, const OracleRay& r, OracleBest& best) {
    // The surface's first crossing along the ray, found independently of the fast path:
    // the pieces between the box, the cutting planes and 16 more samples each are
    // searched for a sign change, which is bisected to 50 digits. (A surface touched
    // without a crossing is not found.)
    const HP a = HP(2) / HP(s.east_west), b = HP(2) / HP(s.north_south);
    HP lo = -1e30, hi = 1e30;
    for (int axis = 0; axis < 3; ++axis) {
        const HP& oa = r.o[axis];
        const HP da = r.d[axis];
        if (da == 0) {
            if (abs(oa) > 1.01) return true;
            continue;
        }
        HP t0 = (-1.01 - oa) / da, t1 = (1.01 - oa) / da;
        if (t0 > t1) std::swap(t0, t1);
        if (t0 > lo) lo = t0;
        if (t1 < hi) hi = t1;
    }
    if (lo < kSuperellipsoidDepthTolerance) lo = kSuperellipsoidDepthTolerance;
    if (!(lo < hi)) return true;
    std::vector<HP> ts{lo, hi};
    for (const auto& c : kCutNormals) {
        const HP den = r.d.x * c[0] + r.d.y * c[1] + r.d.z * c[2];
        if (den == 0) continue;
        const HP t = -(r.o.x * c[0] + r.o.y * c[1] + r.o.z * c[2]) / den;
        if (t > lo && t < hi) ts.push_back(t);
    }
    std::sort(ts.begin(), ts.end());
    std::vector<HP> samples;
    constexpr int kSplit = 16;
    for (size_t i = 0; i + 1 < ts.size(); ++i)
        for (int k = 0; k < kSplit; ++k)
            samples.push_back(ts[i] + (ts[i + 1] - ts[i]) * k / kSplit);
    samples.push_back(ts.back());
    auto f = [&](const HP& t) { return hp_value(a, b, r.o + r.d * t); };
    HP f0 = f(samples[0]);
    if (f0 == 0) {
        best.offer(samples[0], kSuperellipsoidDepthTolerance);
        return true;
    }
    for (size_t i = 1; i < samples.size(); ++i) {
        const HP f1 = f(samples[i]);
        if (f1 == 0 || (f0 < 0) != (f1 < 0)) {
            HP x0 = samples[i - 1], x1 = samples[i];
            for (int k = 0; k < 90 && f1 != 0; ++k) {
                const HP mid = (x0 + x1) / 2;
                const HP fm = f(mid);
                if ((fm < 0) == (f0 < 0))
                    x0 = mid;
                else
                    x1 = mid;
            }
            best.offer(x1, kSuperellipsoidDepthTolerance);
            return true;
        }
        f0 = f1;
    }
    return true;
}

}  // namespace povwall::trace
