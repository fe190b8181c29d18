#include "trace/oracle.h"

#include <boost/multiprecision/cpp_bin_float.hpp>
#include <functional>
#include <iterator>
#include <variant>

#include "trace/intersect.h"
#include "trace/prepared_scene.h"
#include "trace/roots_sturm.h"

namespace povwall::trace {
namespace {

using HP = boost::multiprecision::cpp_bin_float_50;

struct V3 {
    HP x, y, z;
    V3() = default;
    V3(HP a, HP b, HP c) : x(std::move(a)), y(std::move(b)), z(std::move(c)) {}
    explicit V3(const Vector3& v) : x(v.x), y(v.y), z(v.z) {}
    V3 operator+(const V3& o) const { return {x + o.x, y + o.y, z + o.z}; }
    V3 operator-(const V3& o) const { return {x - o.x, y - o.y, z - o.z}; }
    V3 operator*(const HP& s) const { return {x * s, y * s, z * s}; }
    HP operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
};
HP dot(const V3& a, const V3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3 cross(const V3& a, const V3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

// Object-space ray with a unit direction; `scale` turns object distances into world ones.
struct LocalRay {
    V3 o, d;
    HP world_per_object;
};

// The inverse of the object's forward matrix, in 50 digits (not the double inverse the
// tracer uses), so near-singular transforms show up as errors of the fast path.
LocalRay to_object(const Transform& xf, const Ray& ray) {
    const Matrix34& f = xf.forward();
    HP m[3][3], t[3];
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) m[r][c] = f.m[r][c];
        t[r] = f.m[r][3];
    }
    HP det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
             m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
             m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    HP inv[3][3];
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) {
            int r1 = (c + 1) % 3, r2 = (c + 2) % 3, c1 = (r + 1) % 3, c2 = (r + 2) % 3;
            inv[r][c] = (m[r1][c1] * m[r2][c2] - m[r1][c2] * m[r2][c1]) / det;
        }
    }
    V3 po(ray.origin), pd(ray.direction);
    HP rel[3] = {po.x - t[0], po.y - t[1], po.z - t[2]};
    V3 o, d;
    HP* oo[3] = {&o.x, &o.y, &o.z};
    HP* dd[3] = {&d.x, &d.y, &d.z};
    for (int r = 0; r < 3; ++r) {
        *oo[r] = inv[r][0] * rel[0] + inv[r][1] * rel[1] + inv[r][2] * rel[2];
        *dd[r] = inv[r][0] * pd.x + inv[r][1] * pd.y + inv[r][2] * pd.z;
    }
    HP len = sqrt(dot(d, d));
    HP wlen = sqrt(dot(pd, pd));
    return {o, d * (HP(1) / len), wlen / len};
}

// Smallest accepted object-space t, or +inf.
struct Best {
    HP t = std::numeric_limits<HP>::infinity();
    HP floor = 0;  // MIN_ISECT_DEPTH in object units
    void offer(const HP& x, Real tol) {
        if (x > tol && x >= floor && x < t) t = x;
    }
};

void quadratic(const HP& a, const HP& b, const HP& c, Best& best, Real tol,
               const std::function<bool(const HP&)>& keep) {
    if (a == 0) {
        if (b != 0 && keep(-c / b)) best.offer(-c / b, tol);
        return;
    }
    HP disc = b * b - 4 * a * c;
    if (disc < 0) return;
    HP s = sqrt(disc);
    for (HP r : {(-b - s) / (2 * a), (-b + s) / (2 * a)}) {
        if (keep(r)) best.offer(r, tol);
    }
}

void triangle(const V3 p[3], const LocalRay& r, Best& best) {
    V3 e1 = p[1] - p[0], e2 = p[2] - p[0];
    V3 pv = cross(r.d, e2);
    HP det = dot(e1, pv);
    if (det == 0) return;
    V3 tv = r.o - p[0];
    HP u = dot(tv, pv) / det;
    if (u < 0 || u > 1) return;
    V3 qv = cross(tv, e1);
    HP v = dot(r.d, qv) / det;
    if (v < 0 || u + v > 1) return;
    best.offer(dot(e2, qv) / det, kTriangleTolerance);
}

HP axis_frame(const V3& base, const V3& cap, V3& axis) {
    V3 a = cap - base;
    HP l = sqrt(dot(a, a));
    axis = l > 0 ? a * (HP(1) / l) : V3(HP(0), HP(1), HP(0));
    return l;
}

// Object-space first accepted t of one leaf shape.
bool leaf_first(const Object& o, const LocalRay& r, Best& best) {
    const HP eps = kPovEpsilon;
    bool supported = true;
    std::visit(
        [&](const auto& s) {
            using T = std::decay_t<decltype(s)>;
            if constexpr (std::is_same_v<T, Sphere>) {
                V3 oc = V3(s.centre) - r.o;
                HP tca = dot(oc, r.d);
                HP t2hc = HP(s.radius) * s.radius - dot(oc, oc) + tca * tca;
                if (!(t2hc > eps)) return;
                HP th = sqrt(t2hc);
                best.offer(tca - th, kSphereTolerance);
                best.offer(tca + th, kSphereTolerance);
            } else if constexpr (std::is_same_v<T, Box>) {
                Point3 lo = min(s.corner1, s.corner2), hi = max(s.corner1, s.corner2);
                HP tmin = -std::numeric_limits<HP>::infinity(), tmax = -tmin;
                for (int a = 0; a < 3; ++a) {
                    HP oa = r.o[a], da = r.d[a];
                    if (abs(da) < eps) {
                        if (oa < lo[a] || oa > hi[a]) return;
                        continue;
                    }
                    HP t1 = (lo[a] - oa) / da, t2 = (hi[a] - oa) / da;
                    if (t1 > t2) std::swap(t1, t2);
                    tmin = std::max(tmin, t1);
                    tmax = std::min(tmax, t2);
                    if (tmin > tmax) return;
                }
                best.offer(tmin, kBoxTolerance);
                best.offer(tmax, kBoxTolerance);
            } else if constexpr (std::is_same_v<T, Plane>) {
                V3 n(s.normal);
                HP nd = dot(n, r.d);
                if (abs(nd) < eps) return;
                HP t = (HP(s.distance) - dot(n, r.o)) / nd;
                if (t < kMaxDistance) best.offer(t, kPlaneTolerance);
            } else if constexpr (std::is_same_v<T, Disc>) {
                V3 n(normalize(s.normal));
                HP nd = dot(n, r.d);
                if (abs(nd) < eps) return;
                HP t = dot(n, V3(s.centre) - r.o) / nd;
                V3 q = r.o + r.d * t - V3(s.centre);
                HP r2 = dot(q, q);
                if (r2 <= HP(s.radius) * s.radius &&
                    r2 >= HP(s.hole_radius) * s.hole_radius)
                    best.offer(t, kPlaneTolerance);
            } else if constexpr (std::is_same_v<T, Cylinder> || std::is_same_v<T, Cone>) {
                Real r0, r1;
                if constexpr (std::is_same_v<T, Cylinder>) {
                    r0 = r1 = s.radius;
                } else {
                    r0 = s.base_radius;
                    r1 = s.cap_radius;
                }
                V3 axis;
                HP len = axis_frame(V3(s.base), V3(s.cap), axis);
                HP k = (HP(r1) - r0) / len;
                V3 u = r.o - V3(s.base);
                HP dp = dot(r.d, axis), up = dot(u, axis);
                V3 dperp = r.d - axis * dp, uperp = u - axis * up;
                HP rat0 = HP(r0) + k * up;
                auto on_side = [&](const HP& t) {
                    HP h = up + t * dp;
                    return h >= 0 && h <= len && HP(r0) + k * h >= 0;
                };
                quadratic(dot(dperp, dperp) - k * k * dp * dp,
                          2 * (dot(dperp, uperp) - rat0 * k * dp),
                          dot(uperp, uperp) - rat0 * rat0, best, kConeTolerance, on_side);
                if (!s.open && abs(dp) > eps) {
                    for (int cap = 0; cap < 2; ++cap) {
                        HP rr = cap ? r1 : r0;
                        HP t = ((cap ? len : HP(0)) - up) / dp;
                        V3 q = uperp + dperp * t;
                        if (dot(q, q) <= rr * rr) best.offer(t, kConeTolerance);
                    }
                }
            } else if constexpr (std::is_same_v<T, Torus>) {
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
            } else if constexpr (std::is_same_v<T, Triangle> ||
                                 std::is_same_v<T, SmoothTriangle>) {
                if (degenerate_triangle(s.p)) return;
                V3 p[3] = {V3(s.p[0]), V3(s.p[1]), V3(s.p[2])};
                triangle(p, r, best);
            } else if constexpr (std::is_same_v<T, Mesh>) {
                // Single-precision vertices, as POV-Ray keeps them.
                for (const auto& f : s.faces) {
                    V3 p[3] = {V3(single_precision(s.vertices[f.v[0]])),
                               V3(single_precision(s.vertices[f.v[1]])),
                               V3(single_precision(s.vertices[f.v[2]]))};
                    triangle(p, r, best);
                }
            } else if constexpr (std::is_same_v<T, Polygon>) {
                if (s.points.size() < 3 || degenerate_polygon(s)) return;
                V3 n(polygon_normal(s));
                HP nd = dot(n, r.d);
                if (abs(nd) < eps) return;
                HP t = dot(n, V3(s.points[0]) - r.o) / nd;
                if (!(t > kPolygonTolerance) || t > kMaxDistance) return;
                V3 q = r.o + r.d * t;
                Vector3 nn = polygon_normal(s);
                int drop = 0;
                if (std::fabs(nn.y) > std::fabs(nn[drop])) drop = 1;
                if (std::fabs(nn.z) > std::fabs(nn[drop])) drop = 2;
                const int u = drop == 0 ? 1 : 0, v = drop == 2 ? 1 : 2;
                bool inside = false;
                for (size_t i = 0; i < s.points.size(); ++i) {
                    V3 a(s.points[i]), b(s.points[(i + 1) % s.points.size()]);
                    if ((a[v] > q[v]) != (b[v] > q[v])) {
                        HP x = a[u] + (q[v] - a[v]) / (b[v] - a[v]) * (b[u] - a[u]);
                        if (q[u] < x) inside = !inside;
                    }
                }
                if (inside) best.offer(t, kPolygonTolerance);
            } else {
                supported = false;
            }
        },
        o.shape);
    return supported;
}

// Where the ray enters an object's world bounds (t_min if it starts inside), +inf if it
// misses them; generous by 1e-9 relative so rounding never hides an object.
Real bounds_entry(const Object& o, const Ray& ray, Real t_min) {
    const Bounds3 b = object_world_bounds(o);
    Real t0 = t_min, t1 = kInfinity;
    for (int a = 0; a < 3; ++a) {
        const Real pad = 1e-9 * (std::fabs(b.lo[a]) + std::fabs(b.hi[a]) + 1);
        const Real lo = b.lo[a] - pad, hi = b.hi[a] + pad;
        if (ray.direction[a] == 0) {
            if (ray.origin[a] < lo || ray.origin[a] > hi) return kInfinity;
            continue;
        }
        Real ta = (lo - ray.origin[a]) / ray.direction[a];
        Real tb = (hi - ray.origin[a]) / ray.direction[a];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
        if (t0 > t1) return kInfinity;
    }
    return t0;
}

// An object the oracle cannot evaluate only makes the ray unsupported if the ray reaches
// its bounds before the oracle's first hit.
void object_first(const Object& o, const Ray& ray, Real t_min, OracleHit& out,
                  Real& unsupported_from) {
    if (o.no_image) return;
    auto give_up = [&] {
        unsupported_from = std::min(unsupported_from, bounds_entry(o, ray, t_min));
    };
    if (const Csg* csg = std::get_if<Csg>(&o.shape)) {
        if (csg->kind != CsgKind::Union || o.inverse || !o.clipped_by->empty()) {
            give_up();
            return;
        }
        for (const Object& c : csg->children)
            object_first(c, ray, t_min, out, unsupported_from);
        return;
    }
    if (o.inverse || !o.clipped_by->empty()) {
        give_up();
        return;
    }
    LocalRay r = to_object(o.transform, ray);
    Best best;
    best.floor = HP(t_min) / r.world_per_object;
    if (!leaf_first(o, r, best)) {
        give_up();
        return;
    }
    if (!isfinite(best.t)) return;
    HP tw = best.t * r.world_per_object;
    Real t = static_cast<Real>(tw);
    if (t < out.t) {
        out.t = t;
        out.hit = true;
        out.leaf = &o;
    }
}

}  // namespace

std::string shape_kind_name(const Object& leaf) {
    static const char* names[] = {
        "sphere", "box",      "plane",           "cylinder", "cone", "torus",
        "disc",   "triangle", "smooth_triangle", "polygon",  "mesh", "csg"};
    static_assert(std::variant_size_v<ShapeData> == std::size(names),
                  "one name per shape alternative");
    return names[leaf.shape.index()];
}

OracleHit oracle_first_hit(const Scene& scene, const Ray& ray, Real t_min) {
    OracleHit out;
    Real unsupported_from = kInfinity;
    for (const Object& o : scene.objects)
        object_first(o, ray, std::max(t_min, kMinIsectDepth), out, unsupported_from);
    if (unsupported_from < kInfinity && unsupported_from <= out.t) out.supported = false;
    return out;
}

int oracle_quartic_roots(const Real c[5], Real lo, Real hi, Real roots[4]) {
    SturmPoly<HP> p;
    p.degree = 4;
    for (int i = 0; i < 5; ++i) p.c[i] = HP(c[i]) / HP(c[4]);
    HP r[4];
    int n = sturm_real_roots(p, HP(lo), HP(hi), r, 4);
    for (int i = 0; i < n; ++i) roots[i] = static_cast<Real>(r[i]);
    return n;
}

}  // namespace povwall::trace
