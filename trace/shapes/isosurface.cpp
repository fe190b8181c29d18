#include "trace/shapes/isosurface.h"

#include <algorithm>
#include <cmath>

#include "core/function.h"
#include "trace/pattern.h"
#include "trace/shapes/box.h"
#include "trace/shapes/oracle_math.h"

namespace povwall::trace {
namespace {

constexpr Real kIsoBoundHuge = 2e10;  // BOUND_HUGE
constexpr Real kIsoEpsilon = 1e-10;   // EPSILON

// The container's span along o + t d (world distances; d the object-space direction, not
// normalised) and the box faces there as POV-Ray's sides (1..6, 0: none).
bool container_span(const Isosurface& s, const Point3& o, const Vector3& d, Real& t1,
                    Real& t2, int& side1, int& side2) {
    side1 = side2 = 0;
    if (!s.sphere_container) {
        int f1, f2;
        if (!box_span_pov(s.corner1, s.corner2, o, d, t1, t2, f1, f2)) return false;
        side1 = f1 + 1;
        side2 = f2 + 1;
        return true;
    }
    // Sphere::Intersect along the unit direction, then back to world distances.
    const Real len = length(d);
    const Vector3 u = d * (1.0 / len);
    const Vector3 oc = s.centre - o;
    const Real oc2 = dot(oc, oc);
    const Real tca = dot(oc, u);
    const Real r2 = s.radius * s.radius;
    if (oc2 >= r2 && tca < kIsoEpsilon) return false;
    const Real h2 = r2 - oc2 + tca * tca;
    if (!(h2 > kIsoEpsilon)) return false;
    const Real h = std::sqrt(h2);
    t1 = (tca - h) / len;
    t2 = (tca + h) / len;
    return true;
}

struct Evaluator {
    const Isosurface& s;
    PatternEnv env;
    FunctionHooks hooks;
    explicit Evaluator(const Isosurface& iso) : s(iso) {
        env.noise_generator = iso.noise_generator;
        env.number_of_waves = iso.number_of_waves;
        hooks = function_hooks(env);
    }
    Real raw(const Point3& p) const {
        const double args[3] = {p.x, p.y, p.z};
        return evaluate_function(*s.function, args, hooks);
    }
    // POV-Ray's Vector_Function: F - threshold.
    Real operator()(const Point3& p) const { return raw(p) - s.threshold; }
};

// One ray's root search (POV-Ray's Function_Find_Root and its recursion).
struct RootSearch {
    const Evaluator& f;
    Point3 P;
    Vector3 D;
    Real accuracy;
    int sign = 1;  // POV-Ray's Inv3
    Real found = 0;

    Real g(Real t) const { return Real(sign) * f(P + D * t); }

    struct Pair {
        Real t, f;
    };

    bool recurse(const Pair& a, const Pair& b, Real dt, Real w) {
        if (w < accuracy) {
            if (b.f < 0) {
                found = b.t;
                return true;
            }
            return false;
        }
        if (a.f + b.f - dt < 0) {
            w *= 0.5;
            dt *= 0.5;
            Pair m;
            m.t = a.t + w;
            m.f = g(m.t);
            if (!recurse(a, m, dt, w)) return recurse(m, b, dt, w);
            return true;
        }
        return false;
    }

    bool find(Real& t1, Real t2, Real maxg, bool closed) {
        const Real vlength = length(D);
        Pair a{t1, g(t1)};
        if (!closed && a.f < 0.0) {
            sign = -sign;
            a.f = -a.f;
        }
        const Pair b{t2, g(t2)};
        const Real w = t2 - t1;
        const Real dt = maxg * vlength * w;
        if (recurse(a, b, dt, w)) {
            t1 = found;
            return true;
        }
        return false;
    }
};

}  // namespace

Real isosurface_function(const Isosurface& s, const Point3& p) {
    return Evaluator(s).raw(p);
}

namespace {

// One POV-Ray All_Intersections along P + t D (world distances t).
void hits_once(const Isosurface& s, const Point3& P, const Vector3& D, ShapeHits& out) {
    Real depth1 = 0, depth2 = 0;
    int side1, side2;
    if (!container_span(s, P, D, depth1, depth2, side1, side2)) return;
    if (depth1 < 0.0) depth1 = 0.0;
    const Evaluator f(s);
    const Real acc = s.accuracy;
    const Real maxg = s.max_gradient;
    const size_t first = out.size();
    auto push = [&](Real t, int side) { out.push_back({t, P + D * t, side}); };
    int itrace = 0;
    RootSearch search{f, P, D, acc};
    if (s.closed) {
        const Real f1 = f(P + D * depth1);
        if (depth1 > acc) {
            if (f1 < 0.0) {  // the ray meets the container where F is inside
                push(depth1, side1);
                ++itrace;
                search.sign = -search.sign;
            }
        } else {
            if (f1 < maxg * acc * 4.0) {
                depth1 = acc * 5.0;
                if (f(P + D * depth1) < 0) search.sign = -1;
            }
            if (f(P + D * depth2) < 0.0) push(depth2, side2);
        }
    }
    Real tmax = depth2 = std::min(depth2, kIsoBoundHuge);
    Real tmin = depth1 = std::min(depth2, depth1);
    if (tmax - tmin < acc) {
        if (out.size() > first) out.pop_back();
        return;
    }
    if (depth1 < acc && search.sign == 1) {
        // Starting on the surface: step in and look from there.
        if (std::fabs(f(P + D * tmin)) < maxg * acc * 4.0) {
            tmin = acc * 5.0;
            if (f(P + D * tmin) < 0) search.sign = -1;
        }
    }
    for (; itrace < s.max_trace; ++itrace) {
        if (!search.find(tmin, tmax, maxg, s.closed)) break;
        push(tmin, 0);
        tmin += acc * 5.0;
        if (tmax - tmin < acc) break;
        search.sign = -search.sign;
    }
    std::stable_sort(out.begin() + std::ptrdiff_t(first), out.end(),
                     [](const ShapeHit& a, const ShapeHit& b) { return a.t < b.t; });
}

}  // namespace

void shape_hits(const Isosurface& s, const LocalRay& r, ShapeHits& out) {
    const size_t first = out.size();
    hits_once(s, r.origin, r.direction, out);
    if (r.csg_child) return;
    // Outside CSG POV-Ray looks past a hit (a shadow through a transparent isosurface)
    // with a ray restarted there, where povwall follows one ray: the restarts are made
    // here, each from the farthest hit so far.
    thread_local ShapeHits more;
    for (int restart = 0; restart < 32 && out.size() > first; ++restart) {
        const Real t0 = out.back().t;
        more.clear();
        hits_once(s, r.origin + r.direction * t0, r.direction, more);
        bool progressed = false;
        for (const ShapeHit& h : more) {
            if (!(h.t > 0)) continue;
            const Real t = t0 + h.t;
            out.push_back({t, r.origin + r.direction * t, h.face});
            progressed = true;
        }
        if (!progressed) break;
    }
}

Vector3 shape_normal(const Isosurface& s, const ShapeHit& h) {
    if (h.face >= 1 && h.face <= 6) {
        Vector3 n{0, 0, 0};
        n[(h.face - 1) / 2] = (h.face & 1) ? -1.0 : 1.0;
        return n;
    }
    const Point3& q = h.p;
    if (s.sphere_container) {
        const Vector3 v = q - s.centre;
        if (std::fabs(length(v) - s.radius) < kIsoEpsilon) return v * (1.0 / s.radius);
    }
    const Evaluator f(s);
    const Real f0 = f.raw(q);
    Vector3 n{f.raw({q.x + s.accuracy, q.y, q.z}) - f0,
              f.raw({q.x, q.y + s.accuracy, q.z}) - f0,
              f.raw({q.x, q.y, q.z + s.accuracy}) - f0};
    if (n.x == 0 && n.y == 0 && n.z == 0) n.x = 1.0;
    return normalize(n);
}

bool shape_inside(const Isosurface& s, const Point3& p) {
    if (s.sphere_container) {
        const Vector3 v = s.centre - p;
        if (dot(v, v) > s.radius * s.radius) return false;
    } else {
        for (int a = 0; a < 3; ++a)
            if (p[a] < s.corner1[a] || p[a] > s.corner2[a]) return false;
    }
    return !(Evaluator(s)(p) > 0);
}

Bounds3 shape_bounds(const Isosurface& s) {
    if (s.sphere_container)
        return {s.centre - Vector3(s.radius), s.centre + Vector3(s.radius)};
    return {s.corner1, s.corner2};
}

PovBBox shape_pov_bbox(const Isosurface& s, const CompactTransform& xf) {
    PovBBox b;
    for (int a = 0; a < 3; ++a) {
        if (s.sphere_container) {
            b.lo[a] = float(s.centre[a] - s.radius);
            b.len[a] = float(s.radius * 2);
        } else {
            b.lo[a] = float(s.corner1[a]);
            b.len[a] = float(s.corner2[a] - s.corner1[a]);
        }
    }
    // POV-Ray's isosurface always has a matrix: the box always goes through it.
    return pov_bbox(pov_corners_bounds(pov_bbox_bounds(b),
                                       [&](const Point3& p) { return xf.point(p); }));
}

bool shape_oracle_first(const Isosurface& s, const OracleRay& r, OracleBest& best) {
    // The function runs in double, as POV-Ray's: the span inside the container, then the
    // first sign change of F among 4096 samples, bisected to the last bit (a closed
    // container's own surface where F < 0 there). POV-Ray's roots are up to `accuracy`
    // beyond it (the end of the halving step that holds it).
    const Point3 o{double(r.o.x), double(r.o.y), double(r.o.z)};
    const Vector3 d{double(r.d.x), double(r.d.y), double(r.d.z)};
    Real t1 = 0, t2 = 0;
    if (s.sphere_container) {
        const Vector3 oc = o - s.centre;
        const Real b = dot(oc, d), c = dot(oc, oc) - s.radius * s.radius;
        const Real disc = b * b - c;
        if (disc <= 0) return true;
        t1 = -b - std::sqrt(disc);
        t2 = -b + std::sqrt(disc);
    } else {
        t1 = -kInfinity;
        t2 = kInfinity;
        for (int a = 0; a < 3; ++a) {
            if (d[a] == 0) {
                if (o[a] < s.corner1[a] || o[a] > s.corner2[a]) return true;
                continue;
            }
            Real ta = (s.corner1[a] - o[a]) / d[a], tb = (s.corner2[a] - o[a]) / d[a];
            if (ta > tb) std::swap(ta, tb);
            t1 = std::max(t1, ta);
            t2 = std::min(t2, tb);
        }
        if (t1 > t2) return true;
    }
    if (t2 <= 0) return true;
    t1 = std::max(t1, 0.0);
    const Evaluator f(s);
    auto F = [&](Real t) { return f(o + d * t); };
    if (F(t1) < 0) {
        if (s.closed && t1 > 0) best.offer(HP(t1), 0);
        return true;
    }
    constexpr int kSamples = 4096;
    Real prev = t1;
    for (int k = 1; k <= kSamples; ++k) {
        const Real t = t1 + (t2 - t1) * k / kSamples;
        if (F(t) < 0) {
            Real lo = prev, hi = t;
            for (int i = 0; i < 200; ++i) {
                const Real mid = 0.5 * (lo + hi);
                if (mid <= lo || mid >= hi) break;
                (F(mid) < 0 ? hi : lo) = mid;
            }
            best.offer(HP(hi), 0);
            return true;
        }
        prev = t;
    }
    return true;
}

}  // namespace povwall::trace
