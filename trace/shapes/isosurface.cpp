#include "trace/shapes/isosurface.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/function.h"
#include "trace/pattern.h"
#include "trace/shapes/function_container.h"
#include "trace/shapes/oracle_math.h"
#include "trace/shapes/sort_hits.h"

namespace povwall::trace {
namespace {

constexpr Real kIsoBoundHuge = 2e10;  // BOUND_HUGE
constexpr Real kIsoEpsilon = 1e-10;   // EPSILON

FunctionContainer container(const Isosurface& s) {
    return {s.sphere_container, s.corner1, s.corner2, s.centre, s.radius};
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

    // `evaluate` (POV-Ray's dynamic max_gradient): the parameters, null when not given.
    const Real* eval = nullptr;
    IsosurfaceGradients* gradients = nullptr;  // where the statistics go (null: nowhere)
    Real vlength = 0;

    // `len` is 1 / the world length of [a, b]: |b.f - a.f| * len the gradient seen there.
    // The steepest slope between two samples so far (POV-Ray's `gradient`).
    Real steepest = 0;

    bool recurse(const Pair& a, const Pair& b, Real dt, Real w, Real len, Real& maxg) {
        const Real seen = std::fabs((b.f - a.f) * len);
        if (steepest < seen) steepest = seen;
        if (eval) {
            if (maxg < seen * eval[1]) {
                maxg = seen * eval[1] * eval[1];
                dt = maxg * vlength * w;
            }
        }
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
            if (!recurse(a, m, dt, w, len * 2.0, maxg))
                return recurse(m, b, dt, w, len * 2.0, maxg);
            return true;
        }
        return false;
    }

    // maxg: the ray's max_gradient, which `evaluate` changes for the rest of the ray.
    bool find(Real& t1, Real t2, Real& maxg, bool closed) {
        vlength = length(D);
        Pair a{t1, g(t1)};
        if (!closed && a.f < 0.0) {
            sign = -sign;
            a.f = -a.f;
        }
        const Pair b{t2, g(t2)};
        const Real w = t2 - t1;
        // Above P0 the estimate first decays by P2.
        const Real old_maxg = maxg;
        if (eval && maxg > eval[0]) maxg = maxg * eval[2];
        const Real dt = maxg * vlength * w;
        if (recurse(a, b, dt, w, 1.0 / (vlength * w), maxg)) {
            if (eval && gradients) {
                using G = IsosurfaceGradients;
                G::raise(gradients->eval_var, std::fabs(maxg - old_maxg));
                gradients->eval_count.fetch_add(1, std::memory_order_relaxed);
                G::add(gradients->eval_sum, maxg);
                G::raise(gradients->eval_max, maxg);
            }
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

// One POV-Ray All_Intersections along P + t D (world distances t). `maxg` is the
// max_gradient the search starts from; with `evaluate` it is left at the ray's estimate.
// `clip` (or null): the clip, which sees world distances `t_clip + t` (P is t_clip along
// the ray it tests).
void hits_once(const Isosurface& s, const Point3& P, const Vector3& D, Real& maxg,
               const ShapeClip* clip, Real t_clip, ShapeHits& out) {
    Real depth1 = 0, depth2 = 0;
    int side1, side2;
    if (!container_span(container(s), P, D, depth1, depth2, side1, side2)) return;
    if (depth1 < 0.0) depth1 = 0.0;
    const Evaluator f(s);
    const Real acc = s.accuracy;
    const size_t first = out.size();
    auto push = [&](Real t, int side) { out.push_back({t, P + D * t, side}); };
    auto kept = [&](Real t) { return !clip || clip->keeps(clip->context, t_clip + t); };
    int itrace = 0;
    RootSearch search{f, P, D, acc};
    if (s.evaluate) search.eval = s.eval_param;
    search.gradients = s.gradients.get();
    if (s.closed) {
        const Real f1 = f(P + D * depth1);
        if (depth1 > acc) {
            // The ray meets the container where F is inside.
            if (f1 < 0.0 && kept(depth1)) {
                push(depth1, side1);
                ++itrace;
                search.sign = -search.sign;
            }
        } else {
            if (f1 < maxg * acc * 4.0) {
                depth1 = acc * 5.0;
                if (f(P + D * depth1) < 0) search.sign = -1;
            }
            if (f(P + D * depth2) < 0.0 && kept(depth2)) push(depth2, side2);
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
        if (kept(tmin)) push(tmin, 0);
        tmin += acc * 5.0;
        if (tmax - tmin < acc) break;
        search.sign = -search.sign;
    }
    if (search.gradients && search.steepest > 0)
        IsosurfaceGradients::raise(search.gradients->found, search.steepest);
    stable_sort_by_depth(out, first);
}

// The crossings along one ray, as found so far: the first batch (hits_once) and,
// outside CSG, the restarts past it. With `evaluate` POV-Ray writes each search's final
// estimate back into the object (the larger of the two), shared by all later rays of
// every thread, so its image depends on the order of its rays. Here each ray starts from
// the parsed max_gradient (the same image in every mode); its restarts start from its own
// estimate (`reached`), as POV-Ray's restarted ray starts from the written-back one.
struct RayHits {
    ShapeHits hits;
    Real reached = 0;       // the max_gradient estimate the batch ended with
    bool complete = false;  // the restarts are in (or there are none)
};

void first_batch(const Isosurface& s, const LocalRay& r, const ShapeClip* clip,
                 RayHits& h) {
    h.hits.clear();
    h.reached = s.max_gradient;
    // In CSG POV-Ray takes the one batch, from where its ray starts: a shadow ray it
    // restarted at a see-through surface (the CSG's, or another object's) searches
    // afresh from there, so each sheet of the surface dims the light. Outside CSG it
    // looks past a hit with a ray restarted there (add_restarts).
    if (r.csg_child && r.restart > 0) {
        const Real t0 = r.restart;
        thread_local ShapeHits batch;
        batch.clear();
        hits_once(s, r.origin + r.direction * t0, r.direction, h.reached, clip, t0,
                  batch);
        for (const ShapeHit& m : batch) {
            if (!(m.t > 0)) continue;
            const Real t = t0 + m.t;
            h.hits.push_back({t, r.origin + r.direction * t, m.face});
        }
    } else {
        hits_once(s, r.origin, r.direction, h.reached, clip, 0, h.hits);
    }
    h.complete = r.csg_child || h.hits.empty();
}

// povwall follows one ray: the restarts are made here, each from the farthest hit so far.
void add_restarts(const Isosurface& s, const LocalRay& r, const ShapeClip* clip,
                  RayHits& h) {
    Real start = s.max_gradient;
    thread_local ShapeHits more;
    for (int restart = 0; restart < 32 && !h.hits.empty(); ++restart) {
        const Real t0 = h.hits.back().t;
        more.clear();
        start = std::max(start, h.reached);
        h.reached = start;
        hits_once(s, r.origin + r.direction * t0, r.direction, h.reached, clip, t0, more);
        bool progressed = false;
        for (const ShapeHit& m : more) {
            if (!(m.t > 0)) continue;
            const Real t = t0 + m.t;
            h.hits.push_back({t, r.origin + r.direction * t, m.face});
            progressed = true;
        }
        if (!progressed) break;
    }
    h.complete = true;
}

// The restarts only add crossings beyond the first batch's farthest: a query that keeps
// the nearest one in [want_lo, want_hi) (a camera, reflected or shadow ray) has it
// already when the batch holds one at or past want_lo (in the range, or beyond it and so
// are the restarts').
bool answers(const RayHits& h, const LocalRay& r) {
    return h.complete || (r.nearest_only && h.hits.back().t >= r.want_lo);
}

// The last ray's crossings, per thread: a shadow ray through a transparent isosurface
// asks for them once per surface it passes (each time from further along), and the
// root search is the costly part. An equal shape (the same function, held here so that
// its address stays its own, and equal settings) met by the same ray, bit for bit, and
// no clip: the same crossings, whichever scene the shape is in.
bool same_isosurface(const Isosurface& a, const Isosurface& b) {
    return a.function == b.function && a.sphere_container == b.sphere_container &&
           a.corner1 == b.corner1 && a.corner2 == b.corner2 && a.centre == b.centre &&
           a.radius == b.radius && a.threshold == b.threshold &&
           a.accuracy == b.accuracy && a.max_gradient == b.max_gradient &&
           a.max_trace == b.max_trace && a.closed == b.closed &&
           a.evaluate == b.evaluate && a.eval_param[0] == b.eval_param[0] &&
           a.eval_param[1] == b.eval_param[1] && a.eval_param[2] == b.eval_param[2] &&
           a.noise_generator == b.noise_generator &&
           a.number_of_waves == b.number_of_waves;
}

struct LastRay {
    bool valid = false;
    Isosurface shape;
    Point3 origin;
    Vector3 direction;
    bool csg_child = false;
    Real restart = 0;  // a CSG child's batch starts there
    RayHits found;
};

void clipped_hits(const Isosurface& s, const LocalRay& r, const ShapeClip* clip,
                  ShapeHits& out) {
    if (clip) {  // the clip's context is the caller's: nothing to compare
        thread_local RayHits h;
        first_batch(s, r, clip, h);
        if (!answers(h, r)) add_restarts(s, r, clip, h);
        out.insert(out.end(), h.hits.begin(), h.hits.end());
        return;
    }
    thread_local LastRay last;
    const bool same = last.valid && last.origin == r.origin &&
                      last.direction == r.direction && last.csg_child == r.csg_child &&
                      (!r.csg_child || last.restart == r.restart) &&
                      same_isosurface(last.shape, s);
    if (!same) {
        last.valid = true;
        last.shape = s;
        last.origin = r.origin;
        last.direction = r.direction;
        last.csg_child = r.csg_child;
        last.restart = r.restart;
        first_batch(s, r, nullptr, last.found);
    }
    if (!answers(last.found, r)) add_restarts(s, r, nullptr, last.found);
    out.insert(out.end(), last.found.hits.begin(), last.found.hits.end());
}

}  // namespace

void shape_hits(const Isosurface& s, const LocalRay& r, ShapeHits& out) {
    clipped_hits(s, r, nullptr, out);
}

void shape_hits(const Isosurface& s, const LocalRay& r, const ShapeClip& clip,
                ShapeHits& out) {
    clipped_hits(s, r, &clip, out);
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

Bounds3 shape_bounds(const Isosurface& s) { return container_bounds(container(s)); }

PovBBox shape_pov_bbox(const Isosurface& s, const CompactTransform& xf) {
    return container_pov_bbox(container(s), xf);
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

std::vector<std::string> isosurface_messages(const Scene& scene) {
    std::vector<std::string> out;
    auto text = [](const char* format, double a, double b, double c) {
        char buf[512];
        std::snprintf(buf, sizeof buf, format, double(float(a)), double(float(b)),
                      double(float(c)));
        return std::string(buf);
    };
    for (const Object& o : scene.objects) {
        const Isosurface* s = std::get_if<Isosurface>(&o.shape);
        if (!s || s->copy || !s->gradients) continue;
        const IsosurfaceGradients& g = *s->gradients;
        std::string message;
        if (!s->evaluate) {
            const Real found = g.found.load(), set = s->max_gradient;
            if (!(found > kIsoEpsilon && set > kIsoEpsilon)) continue;
            const Real diff = set - found, prop = std::fabs(set / found);
            if ((prop <= 0.9 && diff <= -0.5) ||
                ((prop <= 0.95 || diff <= -0.1) && set < 10.0)) {
                message = text(
                    "The maximum gradient found was %0.3f, but max_gradient of the\n"
                    "isosurface was set to %0.3f. The isosurface may contain holes!\n"
                    "Adjust max_gradient to get a proper rendering of the isosurface.",
                    found, set, 0);
            } else if (diff >= 10.0 || (prop >= 1.1 && diff >= 0.5)) {
                message = text(
                    "The maximum gradient found was %0.3f, but max_gradient of\n"
                    "the isosurface was set to %0.3f. Adjust max_gradient to\n"
                    "get a faster rendering of the isosurface.",
                    found, set, 0);
            }
        } else {
            const Real max = g.eval_max.load(), var = g.eval_var.load();
            const Real diff = max / std::max(max - var, kIsoEpsilon);
            if (s->eval_param[0] > max || s->eval_param[1] > diff) {
                const Real count = std::max(Real(g.eval_count.load()), 1.0);
                message = text(
                    "Evaluate found a maximum gradient of %0.3f and an average\n"
                    "gradient of %0.3f. The maximum gradient variation was %0.3f.",
                    max, g.eval_sum.load() / count, var);
            }
        }
        if (message.empty()) continue;
        const SourceLoc& at = g.function_at;
        const std::string file = at.file >= 0 && size_t(at.file) < scene.files.size()
                                     ? scene.files[size_t(at.file)]
                                     : std::string("?");
        out.push_back(file + ":" + std::to_string(at.line) + ":" +
                      std::to_string(at.column) + ": warning: " + message);
    }
    return out;
}

}  // namespace povwall::trace
