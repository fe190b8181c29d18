#include "trace/shapes/blob.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/math_constants.h"
#include "core/pov_polysolve.h"
#include "trace/roots_sturm.h"
#include "trace/shapes/oracle_math.h"
#include "trace/shapes/sort_hits.h"

namespace povwall::trace {
namespace {

using Kind = BlobElementKind;

constexpr Real kBlobBoundHuge = 2e10;  // BOUND_HUGE
constexpr Real kBlobSmallTolerance = 1e-3;

// The interval of influence of one element along the unit ray P + t D (blob space), as
// POV-Ray's intersect_* functions find it; false when there is none.
bool sphere_interval(const BlobElement& e, const Point3& P, const Vector3& D,
                     Real mindist, Real& tmin, Real& tmax) {
    const Vector3 v = P - e.origin;
    const Real b = dot(v, D);
    const Real t = dot(v, v);
    Real d = b * b - t + e.rad2;
    if (d < kPovEpsilon) return false;
    d = std::sqrt(d);
    tmax = -b + d;
    if (tmax < mindist) tmax = 0.0;
    tmin = -b - d;
    if (tmin < mindist) tmin = 0.0;
    if (tmax == tmin) return false;
    if (tmax < tmin) std::swap(tmin, tmax);
    return true;
}

// The ray in an element's own space, its direction normalised; `len` its length.
void element_ray(const BlobElement& e, const Point3& P, const Vector3& D, Point3& pp,
                 Vector3& dd, Real& len) {
    pp = e.transform.inverse_point(P);
    dd = e.transform.inverse_vector(D);
    len = length(dd);
    dd = dd * (1.0 / len);
}

bool ellipsoid_interval(const BlobElement& e, const Point3& P, const Vector3& D,
                        Real mindist, Real& tmin, Real& tmax) {
    Point3 pp;
    Vector3 dd;
    Real len;
    element_ray(e, P, D, pp, dd, len);
    const Vector3 v = pp - e.origin;
    const Real b = dot(v, dd);
    const Real t = dot(v, v);
    Real d = b * b - t + e.rad2;
    if (d < kPovEpsilon) return false;
    d = std::sqrt(d);
    tmax = (-b + d) / len;
    if (tmax < mindist) tmax = 0.0;
    tmin = (-b - d) / len;
    if (tmin < mindist) tmin = 0.0;
    if (tmax == tmin) return false;
    if (tmax < tmin) std::swap(tmin, tmax);
    return true;
}

bool hemisphere_interval(const BlobElement& e, const Point3& P, const Vector3& D,
                         Real mindist, Real& tmin, Real& tmax) {
    Point3 pp;
    Vector3 dd;
    Real len;
    element_ray(e, P, D, pp, dd, len);
    const bool apex = e.kind == Kind::ApexHemisphere;
    if (apex) pp.z -= e.len;
    const Real b = dot(pp, dd);
    const Real t = dot(pp, pp);
    Real d = b * b - t + e.rad2;
    if (d < kPovEpsilon) return false;
    d = std::sqrt(d);
    tmax = -b + d;
    tmin = -b - d;
    if (tmax < tmin) std::swap(tmin, tmax);
    const Real z1 = pp.z + tmin * dd.z;
    const Real z2 = pp.z + tmax * dd.z;
    // The base half lies at z <= 0, the apex half at z >= 0 (after the shift).
    const bool in1 = apex ? z1 <= 0.0 : z1 >= 0.0;
    const bool in2 = apex ? z2 <= 0.0 : z2 >= 0.0;
    if (in1 && in2) return false;  // the chord is all on the cut-off side
    if (!in1 && !in2) {
        tmin /= len;
        tmax /= len;
        return true;
    }
    const Real tp = -pp.z / dd.z;
    if (in1)
        tmin = tp < mindist ? 0.0 : tp;  // leaving the plane's cut-off side
    else
        tmax = tp < mindist ? 0.0 : tp;
    tmin /= len;
    tmax /= len;
    return true;
}

bool cylinder_interval(const BlobElement& e, const Point3& P, const Vector3& D,
                       Real mindist, Real& tmin, Real& tmax) {
    Point3 pp;
    Vector3 dd;
    Real len;
    element_ray(e, P, D, pp, dd, len);
    auto take = [&](Real t) {
        if (t < tmin) tmin = t;
        if (t > tmax) tmax = t;
    };
    const Real a = dd.x * dd.x + dd.y * dd.y;
    if (a > kPovEpsilon) {
        const Real b = pp.x * dd.x + pp.y * dd.y;
        const Real c = pp.x * pp.x + pp.y * pp.y - e.rad2;
        Real d = b * b - a * c;
        if (d > kPovEpsilon) {
            d = std::sqrt(d);
            Real t = (-b + d) / a;
            Real w = pp.z + t * dd.z;
            if (w >= 0.0 && w <= e.len) take(t);
            t = (-b - d) / a;
            w = pp.z + t * dd.z;
            if (w >= 0.0 && w <= e.len) take(t);
        }
    }
    if (std::fabs(dd.z) > kPovEpsilon) {
        Real t = -pp.z / dd.z;
        Real u = pp.x + t * dd.x;
        Real v = pp.y + t * dd.y;
        if (u * u + v * v <= e.rad2) take(t);
        t = (e.len - pp.z) / dd.z;
        u = pp.x + t * dd.x;
        v = pp.y + t * dd.y;
        if (u * u + v * v <= e.rad2) take(t);
    }
    tmin /= len;
    tmax /= len;
    if (tmin < mindist) tmin = 0.0;
    if (tmax < mindist) tmax = 0.0;
    return tmin < tmax;
}

bool element_interval(const BlobElement& e, const Point3& P, const Vector3& D,
                      Real mindist, Real& tmin, Real& tmax) {
    tmin = kBlobBoundHuge;
    tmax = -kBlobBoundHuge;
    switch (e.kind) {
        case Kind::Sphere:
            return sphere_interval(e, P, D, mindist, tmin, tmax);
        case Kind::Ellipsoid:
            return ellipsoid_interval(e, P, D, mindist, tmin, tmax);
        case Kind::BaseHemisphere:
        case Kind::ApexHemisphere:
            return hemisphere_interval(e, P, D, mindist, tmin, tmax);
        case Kind::Cylinder:
            return cylinder_interval(e, P, D, mindist, tmin, tmax);
    }
    return false;
}

struct Event {
    Real bound;
    int element;
    bool exiting;
};

// POV-Ray's insert_hit: the entry before the first bound not below t0, the exit after
// it before the first bound not below t1.
void insert_interval(std::vector<Event>& ev, int element, Real t0, Real t1) {
    size_t k = 0;
    while (k < ev.size() && t0 > ev[k].bound) ++k;
    ev.insert(ev.begin() + std::ptrdiff_t(k), {t0, element, false});
    size_t j = k + 1;
    while (j < ev.size() && t1 > ev[j].bound) ++j;
    ev.insert(ev.begin() + std::ptrdiff_t(j), {t1, element, true});
}

// The list insert_interval builds from the intervals in their order, in O(n log n): while
// every interval has t0 < t1 the list stays sorted and each bound goes before the equal
// ones already there, so the list is the bounds sorted, ties latest first. Otherwise
// (a hemisphere's interval clamped behind the ray) the insertions themselves.
struct Interval {
    int element;
    Real t0, t1;
};
void sort_intervals(const std::vector<Interval>& in, std::vector<Event>& ev) {
    ev.clear();
    const bool ordered =
        std::all_of(in.begin(), in.end(), [](const Interval& i) { return i.t0 < i.t1; });
    if (!ordered) {
        for (const Interval& i : in) insert_interval(ev, i.element, i.t0, i.t1);
        return;
    }
    thread_local std::vector<std::pair<Event, uint32_t>> keyed;
    keyed.clear();
    uint32_t seq = 0;
    for (const Interval& i : in) {
        keyed.push_back({{i.t0, i.element, false}, seq++});
        keyed.push_back({{i.t1, i.element, true}, seq++});
    }
    std::sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) {
        return a.first.bound < b.first.bound ||
               (a.first.bound == b.first.bound && a.second > b.second);
    });
    for (const auto& k : keyed) ev.push_back(k.first);
}

// The elements whose region the line P + t D may meet, in their stored order (the order
// POV-Ray's list without the tree visits them, which the sums keep).
const std::vector<uint32_t>& line_elements(const BlobData& d, const Point3& P,
                                           const Vector3& D) {
    thread_local std::vector<uint32_t> found;
    found.clear();
    if (d.tree.empty() || d.tree.element_count() != d.elements.size()) {
        for (uint32_t i = 0; i < uint32_t(d.elements.size()); ++i) found.push_back(i);
        return found;
    }
    d.tree.line_candidates(P, D, found);
    std::sort(found.begin(), found.end());
    return found;
}

// The element's quartic along P + s D (D not unit: the blob's ray scaled to the span of
// the intervals), highest power first.
void element_coefficients(const BlobElement& e, const Point3& P, const Vector3& D,
                          Real max_bound, Real* f) {
    Real t0, t1, t2;
    switch (e.kind) {
        case Kind::Sphere: {
            const Vector3 v = P - e.origin;
            t0 = dot(v, v);
            t1 = dot(v, D);
            t2 = max_bound * max_bound;
            break;
        }
        case Kind::Ellipsoid: {
            const Vector3 v = e.transform.inverse_point(P) - e.origin;
            const Vector3 dd = e.transform.inverse_vector(D);
            t0 = dot(v, v);
            t1 = dot(v, dd);
            t2 = dot(dd, dd);
            break;
        }
        case Kind::BaseHemisphere:
        case Kind::ApexHemisphere: {
            Point3 pp = e.transform.inverse_point(P);
            const Vector3 dd = e.transform.inverse_vector(D);
            if (e.kind == Kind::ApexHemisphere) pp.z -= e.len;
            t0 = dot(pp, pp);
            t1 = dot(pp, dd);
            t2 = dot(dd, dd);
            break;
        }
        case Kind::Cylinder:
        default: {
            const Point3 pp = e.transform.inverse_point(P);
            const Vector3 dd = e.transform.inverse_vector(D);
            t0 = pp.x * pp.x + pp.y * pp.y;
            t1 = pp.x * dd.x + pp.y * dd.y;
            t2 = dd.x * dd.x + dd.y * dd.y;
            break;
        }
    }
    const Real c0 = e.c[0], c1 = e.c[1], c2 = e.c[2];
    f[0] = c0 * t2 * t2;
    f[1] = 4.0 * c0 * t1 * t2;
    f[2] = 2.0 * c0 * (2.0 * t1 * t1 + t0 * t2) + c1 * t2;
    f[3] = 2.0 * t1 * (2.0 * c0 * t0 + c1);
    f[4] = t0 * (c0 * t0 + c1) + c2;
}

// Whether the quartic c on [l, l + w] surely has no root: the control values of its
// Bezier form on that piece all have one sign.
bool hull_misses(const Real* c, Real l, Real w) {
    Real n[5];
    n[0] = c[0] * w * w * w * w;
    n[1] = (c[1] + 4.0 * c[0] * l) * w * w * w;
    n[2] = (3.0 * l * (2.0 * c[0] * l + c[1]) + c[2]) * w * w;
    n[3] = (2.0 * l * (2.0 * l * (c[0] * l + 0.75 * c[1]) + c[2]) + c[3]) * w;
    n[4] = l * (l * (l * (c[0] * l + c[1]) + c[2]) + c[3]) + c[4];
    Real dk[5];
    dk[0] = n[4];
    dk[1] = n[4] + 0.25 * n[3];
    dk[2] = n[4] + 0.50 * (n[3] + n[2] / 3.0);
    dk[3] = n[4] + 0.50 * (1.5 * n[3] + n[2] + 0.5 * n[1]);
    dk[4] = n[4] + n[3] + n[2] + n[1] + n[0];
    bool pos = true, neg = true;
    for (Real v : dk) {
        pos = pos && v >= 0.0;
        neg = neg && v <= 0.0;
    }
    return pos || neg;
}

// The value r2 the element measures at `p` (blob space) and the vector whose gradient it
// is, when p is in the element's region (false otherwise). `inclusive`: the sphere's
// own boundary counts (the normal's test; the field's is strict for spheres).
bool element_at(const BlobElement& e, const Point3& p, bool inclusive, Real& r2,
                Vector3& v) {
    switch (e.kind) {
        case Kind::Sphere:
            v = p - e.origin;
            r2 = dot(v, v);
            return inclusive ? r2 <= e.rad2 : r2 < e.rad2;
        case Kind::Ellipsoid:
            v = e.transform.inverse_point(p) - e.origin;
            r2 = dot(v, v);
            return inclusive ? r2 <= e.rad2 : r2 < e.rad2;
        case Kind::BaseHemisphere:
            v = e.transform.inverse_point(p);
            if (!(v.z <= 0.0)) return false;
            r2 = dot(v, v);
            return r2 <= e.rad2;
        case Kind::ApexHemisphere:
            v = e.transform.inverse_point(p);
            v.z -= e.len;
            if (!(v.z >= 0.0)) return false;
            r2 = dot(v, v);
            return r2 <= e.rad2;
        case Kind::Cylinder:
            v = e.transform.inverse_point(p);
            if (!(v.z >= 0.0 && v.z <= e.len)) return false;
            r2 = v.x * v.x + v.y * v.y;
            v.z = 0.0;
            return r2 <= e.rad2;
    }
    return false;
}

}  // namespace

Real blob_element_field(const BlobElement& e, const Point3& p) {
    Real r2;
    Vector3 v;
    if (!element_at(e, p, false, r2, v)) return 0.0;
    return r2 * (r2 * e.c[0] + e.c[1]) + e.c[2];
}

void blob_elements_at(const BlobData& d, const Point3& p, std::vector<uint32_t>& out) {
    out.clear();
    if (d.tree.empty() || d.tree.element_count() != d.elements.size()) {
        for (uint32_t i = 0; i < uint32_t(d.elements.size()); ++i) out.push_back(i);
        return;
    }
    d.tree.point_candidates(p, out);
    std::sort(out.begin(), out.end());
}

Real blob_field(const BlobData& d, const Point3& p) {
    thread_local std::vector<uint32_t> near;
    blob_elements_at(d, p, near);
    Real density = 0.0;
    for (const uint32_t i : near) {
        const BlobElement& e = d.elements[i];
        Real r2;
        Vector3 v;
        if (element_at(e, p, false, r2, v))
            density += r2 * (r2 * e.c[0] + e.c[1]) + e.c[2];
    }
    return density;
}

Vector3 blob_gradient(const BlobData& d, const Point3& p) {
    thread_local std::vector<uint32_t> near;
    blob_elements_at(d, p, near);
    Vector3 n{0, 0, 0};
    for (const uint32_t i : near) {
        const BlobElement& e = d.elements[i];
        Real r2;
        Vector3 v;
        if (!element_at(e, p, true, r2, v)) continue;
        const Real val = -2.0 * e.c[0] * r2 - e.c[1];
        if (e.kind != Kind::Sphere) v = e.transform.normal(v);
        n = n + v * val;
    }
    const Real l2 = dot(n, n);
    if (l2 == 0.0) return {1, 0, 0};
    return n * (1.0 / std::sqrt(l2));
}

void blob_element_sphere(const BlobElement& e, Point3& centre, Real& radius2) {
    switch (e.kind) {
        case Kind::Sphere:
        case Kind::Ellipsoid:
            radius2 = e.rad2;
            centre = e.origin;
            break;
        case Kind::BaseHemisphere:
            radius2 = e.rad2;
            centre = {0, 0, 0};
            break;
        case Kind::ApexHemisphere:
            radius2 = e.rad2;
            centre = {0, 0, e.len};
            break;
        case Kind::Cylinder:
            centre = {0, 0, 0.5 * e.len};
            radius2 = e.rad2 + (0.5 * e.len) * (0.5 * e.len);
            break;
    }
    if (e.kind == Kind::Sphere) return;
    // Through the element's matrix: the centre mapped, the radius the largest side of
    // the box [0, r]^3 moved by it (single precision, as POV-Ray's boxes).
    const Real r = std::sqrt(radius2);
    centre = e.transform.point(centre);
    PovBBox cube;
    for (float& l : cube.len) l = float(r);
    const PovBBox moved = pov_bbox(pov_corners_bounds(
        pov_bbox_bounds(cube), [&](const Point3& q) { return e.transform.point(q); }));
    const Real side =
        std::max({std::fabs(Real(moved.len[0])), std::fabs(Real(moved.len[1])),
                  std::fabs(Real(moved.len[2]))});
    radius2 = side * side + kPovEpsilon;
}

void shape_hits(const Blob& s, const LocalRay& r, ShapeHits& out) {
    const BlobData& d = *s.data;
    Point3 P = r.origin;
    Vector3 D = r.transformed ? r.unit : r.direction;
    const Real len = r.transformed ? r.length : 1.0;
    const Real mindist = kBlobDepthTolerance;

    thread_local std::vector<Interval> intervals;
    thread_local std::vector<Event> ev;
    thread_local std::vector<Real> fcoeffs;
    intervals.clear();
    for (const uint32_t i : line_elements(d, P, D)) {
        Real t0, t1;
        if (element_interval(d.elements[i], P, D, mindist, t0, t1))
            intervals.push_back({int(i), t0, t1});
    }
    if (intervals.empty()) return;
    sort_intervals(intervals, ev);

    // Start at the first interval; scale the ray so that the intervals span [0, 1].
    Real start = ev[0].bound;
    if (start < kBlobSmallTolerance) start = 0.0;
    for (Event& e : ev) e.bound -= start;
    P = P + D * start;
    Real max_bound = ev[0].bound;
    for (const Event& e : ev) max_bound = std::max(max_bound, e.bound);
    if (max_bound != 0) {
        D = D * max_bound;
        for (Event& e : ev) e.bound /= max_bound;
    } else {
        max_bound = 1;
    }

    fcoeffs.resize(d.elements.size() * 5);
    Real coeffs[5] = {0.0, 0.0, 0.0, 0.0, -d.threshold};
    const size_t first = out.size();
    int active = 0;
    const size_t cnt = ev.size();
    for (size_t i = 0; i < cnt; ++i) {
        Real* f = &fcoeffs[size_t(ev[i].element) * 5];
        if (!ev[i].exiting) {
            ++active;
            element_coefficients(d.elements[size_t(ev[i].element)], P, D, max_bound, f);
            for (int j = 0; j < 5; ++j) coeffs[j] += f[j];
        } else {
            for (int j = 0; j < 5; ++j) coeffs[j] -= f[j];
            if (--active == 0) continue;
        }
        if (i + 1 >= cnt) continue;  // (POV-Ray reads past its list here; never reached)
        // A neighbouring bound: take its change in before looking for roots.
        if (std::fabs(ev[i].bound - ev[i + 1].bound) < kPovEpsilon) continue;
        const Real lo = ev[i].bound, hi = ev[i + 1].bound;
        // Every root from here on is at least this far (the distance grows with the
        // root): past the wanted range, none is wanted.
        if (r.nearest_only && (lo * max_bound + start) / len >= r.want_hi) break;
        if (hull_misses(coeffs, lo, hi - lo)) continue;
        Real roots[4];
        const int nroots = pov_solve_polynomial(4, coeffs, roots, s.sturm, 1.0e-11);
        bool wanted = false;
        for (int j = 0; j < nroots; ++j) {
            const Real root = roots[j];
            if (!(root >= lo && root <= hi)) continue;
            const Real dist = (root * max_bound + start) / len;
            if (dist > kBlobDepthTolerance && dist < kMaxDistance) {
                out.push_back({dist, r.origin + r.direction * dist, 0});
                wanted = wanted || (dist >= r.want_lo && dist < r.want_hi);
            }
        }
        // POV-Ray stops here outside CSG once an interval gave a hit: the later ones are
        // farther, and it finds them again from a ray restarted at the hit (shadows
        // through a transparent blob). povwall follows one ray through every crossing, so
        // it keeps them all, unless the query wants only the nearest in its range.
        if (wanted && r.nearest_only) break;
    }
    stable_sort_by_depth(out, first);
}

Vector3 shape_normal(const Blob& s, const ShapeHit& h) {
    return blob_gradient(*s.data, h.p);
}

bool shape_inside(const Blob& s, const Point3& p) {
    return blob_field(*s.data, p) > s.data->threshold - kBlobInsideTolerance;
}

Bounds3 shape_bounds(const Blob& s) {
    // Every element's sphere: the intervals where hits are looked for lie in them.
    Bounds3 b;
    for (const BlobElement& e : s.data->elements) {
        Point3 c;
        Real r2;
        blob_element_sphere(e, c, r2);
        const Real r = std::sqrt(r2);
        b.extend(Bounds3{c - Vector3(r), c + Vector3(r)});
    }
    return b;
}

PovBBox shape_pov_bbox(const Blob& s, const CompactTransform& xf) {
    // POV-Ray's Compute_BBox: the positive elements' spheres only.
    Bounds3 b{{kBlobBoundHuge, kBlobBoundHuge, kBlobBoundHuge},
              {-kBlobBoundHuge, -kBlobBoundHuge, -kBlobBoundHuge}};
    for (const BlobElement& e : s.data->elements) {
        if (!(e.c[2] > 0.0)) continue;
        Point3 c;
        Real r2;
        blob_element_sphere(e, c, r2);
        const Real r = std::sqrt(r2);
        for (int a = 0; a < 3; ++a) {
            b.lo[a] = std::min(b.lo[a], c[a] - r);
            b.hi[a] = std::max(b.hi[a], c[a] + r);
        }
    }
    const PovBBox own = pov_bbox(b);
    if (xf.is_identity()) return own;
    return pov_bbox(pov_corners_bounds(pov_bbox_bounds(own),
                                       [&](const Point3& p) { return xf.point(p); }));
}

namespace {

V3 hp_apply(const Matrix34& m, const V3& v, bool point) {
    V3 r;
    for (int i = 0; i < 3; ++i) {
        HP s = HP(m.m[i][0]) * v.x + HP(m.m[i][1]) * v.y + HP(m.m[i][2]) * v.z;
        if (point) s += HP(m.m[i][3]);
        (i == 0 ? r.x : i == 1 ? r.y : r.z) = s;
    }
    return r;
}

// An element's r^2 along the ray as a t^2 + b t + c, and the coordinate z(t) = z0 + t dz
// its region is cut by (in its own space).
struct HpElementRay {
    HP a, b, c, z0, dz;
};

HpElementRay hp_element_ray(const BlobElement& e, const OracleRay& r) {
    V3 o = r.o, d = r.d;
    if (e.kind != Kind::Sphere) {
        o = hp_apply(e.transform.inverse_matrix(), o, true);
        d = hp_apply(e.transform.inverse_matrix(), d, false);
    }
    if (e.kind == Kind::Sphere || e.kind == Kind::Ellipsoid) o = o - V3(e.origin);
    if (e.kind == Kind::ApexHemisphere) o.z -= HP(e.len);
    HpElementRay er;
    er.z0 = o.z;
    er.dz = d.z;
    if (e.kind == Kind::Cylinder) {
        o.z = 0;
        d.z = 0;
    }
    er.a = dot(d, d);
    er.b = 2 * dot(o, d);
    er.c = dot(o, o);
    return er;
}

bool hp_in_region(const BlobElement& e, const HpElementRay& er, const HP& t) {
    const HP r2 = (er.a * t + er.b) * t + er.c;
    const HP z = er.z0 + t * er.dz;
    switch (e.kind) {
        case Kind::Sphere:
        case Kind::Ellipsoid:
            return r2 < HP(e.rad2);
        case Kind::BaseHemisphere:
            return z <= 0 && r2 <= HP(e.rad2);
        case Kind::ApexHemisphere:
            return z >= 0 && r2 <= HP(e.rad2);
        case Kind::Cylinder:
            return z >= 0 && z <= HP(e.len) && r2 <= HP(e.rad2);
    }
    return false;
}

}  // namespace

bool shape_oracle_first(const Blob& s, const OracleRay& r, OracleBest& best) {
    // The field along the ray is a quartic between the points where an element's region
    // starts or ends: each piece's quartic minus the threshold, its roots by Sturm in 50
    // digits.
    const BlobData& d = *s.data;
    std::vector<HpElementRay> ers;
    std::vector<HP> cuts{HP(0), HP(kMaxDistance)};
    for (const BlobElement& e : d.elements) {
        const HpElementRay er = hp_element_ray(e, r);
        ers.push_back(er);
        const HP disc = er.b * er.b - 4 * er.a * (er.c - HP(e.rad2));
        if (er.a > 0 && disc >= 0) {
            const HP q = sqrt(disc);
            cuts.push_back((-er.b - q) / (2 * er.a));
            cuts.push_back((-er.b + q) / (2 * er.a));
        }
        if (e.kind != Kind::Sphere && e.kind != Kind::Ellipsoid && er.dz != 0) {
            cuts.push_back(-er.z0 / er.dz);
            if (e.kind == Kind::Cylinder) cuts.push_back((HP(e.len) - er.z0) / er.dz);
        }
    }
    std::sort(cuts.begin(), cuts.end());
    const Real tol = kBlobDepthTolerance / double(r.world_per_object);
    for (size_t k = 0; k + 1 < cuts.size(); ++k) {
        const HP lo = cuts[k], hi = cuts[k + 1];
        if (lo < 0 || !(lo < hi)) continue;
        if (lo > best.t) break;
        const HP mid = (lo + hi) / 2;
        SturmPoly<HP, 4> p;
        for (HP& c : p.c) c = 0;
        p.c[0] = -HP(d.threshold);
        bool any = false;
        for (size_t i = 0; i < d.elements.size(); ++i) {
            const BlobElement& e = d.elements[i];
            const HpElementRay& er = ers[i];
            if (!hp_in_region(e, er, mid)) continue;
            any = true;
            // c0 r2^2 + c1 r2 + c2 with r2 = a t^2 + b t + c.
            const HP c0 = e.c[0], c1 = e.c[1], c2 = e.c[2];
            p.c[4] += c0 * er.a * er.a;
            p.c[3] += c0 * 2 * er.a * er.b;
            p.c[2] += c0 * (er.b * er.b + 2 * er.a * er.c) + c1 * er.a;
            p.c[1] += c0 * 2 * er.b * er.c + c1 * er.b;
            p.c[0] += c0 * er.c * er.c + c1 * er.c + c2;
        }
        if (!any) continue;
        p.degree = 4;
        while (p.degree >= 0 && p.c[p.degree] == 0) --p.degree;
        HP roots[4];
        const int n = sturm_real_roots(p, lo, hi, roots, 4);
        for (int j = 0; j < n; ++j) best.offer(roots[j], tol);
    }
    return true;
}

}  // namespace povwall::trace
