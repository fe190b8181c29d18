#include "trace/shapes/parametric.h"

#include <algorithm>
#include <cmath>

#include "core/parametric.h"
#include "trace/pattern.h"
#include "trace/shapes/function_container.h"
#include "trace/shapes/oracle_math.h"

namespace povwall::trace {
namespace {

constexpr int kMaxSector = 10000000;  // POV-Ray's Max_intNumber

FunctionContainer container(const Parametric& s) {
    return {s.sphere_container, s.corner1, s.corner2, s.centre, s.radius};
}

struct Functions {
    const Parametric& s;
    PatternEnv env;
    FunctionHooks hooks;
    explicit Functions(const Parametric& p) : s(p) {
        env.noise_generator = p.noise_generator;
        env.number_of_waves = p.number_of_waves;
        hooks = function_hooks(env);
    }
    Real at(int axis, Real u, Real v) const {
        return parametric_coordinate(*s.functions[axis], hooks, u, v);
    }
    Point3 point(Real u, Real v) const { return {at(0, u, v), at(1, u, v), at(2, u, v)}; }
};

// A piece of the uv rectangle and its index in the precompute tree.
struct Piece {
    Real lo[2], hi[2];  // u, v
    int sector;
};

}  // namespace

void shape_hits(const Parametric& s, const LocalRay& r, ShapeHits& out) {
    Real depth1 = 0, depth2 = 0;
    int side1, side2;
    if (!container_span(container(s), r.origin, r.direction, depth1, depth2, side1,
                        side2))
        return;
    const Point3& P = r.origin;
    const Vector3& D = r.direction;
    const Real acc = s.accuracy;
    if (depth1 == depth2) depth1 = 0;
    if ((depth1 += 4 * acc) > depth2) return;
    const Functions f(s);
    int precomputed[3] = {0, 0, 0};  // sectors below this have precomputed bounds
    if (s.precompute) {
        for (int a = 0; a < 3; ++a)
            if (s.precompute->axis[a]) precomputed[a] = 1 << s.precompute->depth;
    }
    bool parallel[3];
    for (int a = 0; a < 3; ++a) parallel[a] = std::fabs(D[a]) < kPovEpsilon;

    thread_local std::vector<Piece> stack;
    stack.clear();
    stack.push_back({{s.umin, s.vmin}, {s.umax, s.vmax}, 1});
    Real best = HUGE_VAL;
    Real best_u = 0, best_v = 0;
    Real candidate = 0;  // POV-Ray's TPotRes: the last axis span's start
    while (!stack.empty()) {
        const Piece piece = stack.back();
        Real len = piece.hi[0] - piece.lo[0];
        int split = 0;
        if (piece.hi[1] - piece.lo[1] > len) {
            len = piece.hi[1] - piece.lo[1];
            split = 1;
        }
        Real span_lo[3], span_hi[3];
        Real span_len = 0;
        bool dropped = false;
        for (int a = 0; a < 3 && !dropped; ++a) {
            Real low, high;
            // POV-Ray reads z's precomputed bounds only past sector 0 (always so).
            if (piece.sector < precomputed[a] && (a < 2 || piece.sector > 0)) {
                low = s.precompute->low[a][size_t(piece.sector)];
                high = s.precompute->high[a][size_t(piece.sector)];
            } else {
                parametric_interval(*s.functions[a], f.hooks, acc, s.max_gradient,
                                    piece.lo[0], piece.lo[1], piece.hi[0], piece.hi[1],
                                    low, high);
            }
            if (parallel[a]) {
                dropped = high < P[a] || low > P[a];
                continue;
            }
            Real t0 = (high - P[a]) / D[a], t1 = (low - P[a]) / D[a];
            if (t0 > t1) std::swap(t0, t1);
            if (t0 > depth2 || t1 < depth1) {
                dropped = true;
                continue;
            }
            if ((candidate = t0) > best) {
                dropped = true;
                continue;
            }
            for (int b = 0; b < a && !dropped; ++b)
                dropped = !parallel[b] && (t0 > span_hi[b] || t1 < span_lo[b]);
            if (dropped) continue;
            span_lo[a] = t0;
            span_hi[a] = t1;
            span_len = std::max(span_len, t1 - t0);
        }
        if (dropped) {
            stack.pop_back();
            continue;
        }
        if (len > span_len) len = span_len;
        if (len < acc) {
            if (best > candidate && candidate > depth1) {
                best = candidate;
                best_u = piece.lo[0];
                best_v = piece.lo[1];
            }
            stack.pop_back();
            continue;
        }
        // Split across the longer side: the lower half (sector 2n) is searched first,
        // the upper one (2n + 1) stays where the piece was.
        const int n = std::min(piece.sector * 2, kMaxSector);
        Piece lower = piece;
        lower.sector = n;
        const Real mid = (piece.hi[split] + piece.lo[split]) / 2.0;
        lower.hi[split] = mid;
        Piece& upper = stack.back();
        upper.sector = n + 1;
        upper.lo[split] = mid;
        stack.push_back(lower);
    }
    if (best < depth2) {
        ShapeHit h{best, P + D * best, 0};
        h.param = best_u;
        h.param2 = best_v;
        out.push_back(h);
    }
}

Vector3 shape_normal(const Parametric& s, const ShapeHit& h) {
    const Functions f(s);
    const Real u = h.param, v = h.param2;
    Vector3 du, dv;
    for (int a = 0; a < 3; ++a) {
        const Real here = f.at(a, u, v);
        du[a] = -here + f.at(a, u + s.accuracy, v);
        dv[a] = -here + f.at(a, u, v + s.accuracy);
    }
    return cross(du, dv);
}

bool shape_inside(const Parametric&, const Point3&) { return false; }

Bounds3 shape_bounds(const Parametric& s) { return container_bounds(container(s)); }

PovBBox shape_pov_bbox(const Parametric& s, const CompactTransform& xf) {
    return container_pov_bbox(container(s), xf);
}

namespace {

// The surface sampled on a grid of the uv rectangle (the oracle's start), kept for the
// last parametric a thread asked about (its functions held, so no other can take their
// place).
struct SampledSurface {
    std::shared_ptr<const FunctionProgram> functions[3];
    Real umin = 0, vmin = 0, umax = 0, vmax = 0;
    static constexpr int kSteps = 160;
    std::vector<Point3> points;  // (kSteps + 1)^2, u fastest
    bool same(const Parametric& s) const {
        for (int a = 0; a < 3; ++a)
            if (functions[a] != s.functions[a]) return false;
        return umin == s.umin && vmin == s.vmin && umax == s.umax && vmax == s.vmax;
    }
    Real u(int i) const { return umin + (umax - umin) * i / kSteps; }
    Real v(int j) const { return vmin + (vmax - vmin) * j / kSteps; }
};

const SampledSurface& sampled(const Parametric& s, const Functions& f) {
    thread_local SampledSurface grid;
    if (!grid.points.empty() && grid.same(s)) return grid;
    for (int a = 0; a < 3; ++a) grid.functions[a] = s.functions[a];
    grid.umin = s.umin;
    grid.vmin = s.vmin;
    grid.umax = s.umax;
    grid.vmax = s.vmax;
    grid.points.clear();
    for (int j = 0; j <= SampledSurface::kSteps; ++j)
        for (int i = 0; i <= SampledSurface::kSteps; ++i)
            grid.points.push_back(f.point(grid.u(i), grid.v(j)));
    return grid;
}

// The ray's crossing of the plane of triangle abc (t along the unit direction) where it
// is in the triangle or near it (barycentric coordinates down to -kNear): a ray that
// grazes the curved surface between samples may miss the flat pieces.
constexpr Real kNear = 0.3;
bool triangle_crossing(const Point3& o, const Vector3& d, const Point3& a,
                       const Point3& b, const Point3& c, Real& t, Real& s1, Real& s2) {
    const Vector3 e1 = b - a, e2 = c - a;
    const Vector3 p = cross(d, e2);
    const Real det = dot(e1, p);
    if (det == 0) return false;
    const Real inv = 1.0 / det;
    const Vector3 q = o - a;
    s1 = dot(q, p) * inv;
    if (s1 < -kNear || s1 > 1 + kNear) return false;
    const Vector3 qe = cross(q, e1);
    s2 = dot(d, qe) * inv;
    if (s2 < -kNear || s1 + s2 > 1 + kNear) return false;
    t = dot(e2, qe) * inv;
    return true;
}

}  // namespace

bool shape_oracle_first(const Parametric& s, const OracleRay& r, OracleBest& best) {
    // The functions run in double, as POV-Ray's. The span inside the container first
    // (POV-Ray finds nothing outside it), then the grid's triangles crossed or nearly
    // crossed, nearest first, each polished by Newton on S(u, v) - (o + t d) = 0 in (u,
    // v, t); the nearest polished point inside the rectangle and the span is the
    // surface's first.
    const Point3 o{double(r.o.x), double(r.o.y), double(r.o.z)};
    const Vector3 d{double(r.d.x), double(r.d.y), double(r.d.z)};
    Real t_in = 0, t_out = 0;
    int side1, side2;
    if (!container_span(container(s), o, d, t_in, t_out, side1, side2)) return true;
    const Functions f(s);
    const SampledSurface& grid = sampled(s, f);
    struct Candidate {
        Real t, u, v;
    };
    std::vector<Candidate> candidates;
    const int n = SampledSurface::kSteps;
    auto at = [&](int i, int j) -> const Point3& {
        return grid.points[size_t(j) * size_t(n + 1) + size_t(i)];
    };
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            const Point3 &p00 = at(i, j), &p10 = at(i + 1, j), &p01 = at(i, j + 1),
                         &p11 = at(i + 1, j + 1);
            Real t, a, b;
            if (triangle_crossing(o, d, p00, p10, p01, t, a, b))
                candidates.push_back({t, grid.u(i) + a * (grid.u(i + 1) - grid.u(i)),
                                      grid.v(j) + b * (grid.v(j + 1) - grid.v(j))});
            if (triangle_crossing(o, d, p11, p01, p10, t, a, b))
                candidates.push_back({t, grid.u(i + 1) + a * (grid.u(i) - grid.u(i + 1)),
                                      grid.v(j + 1) + b * (grid.v(j) - grid.v(j + 1))});
        }
    }
    std::sort(candidates.begin(), candidates.end(),
              [](const Candidate& a, const Candidate& b) { return a.t < b.t; });
    const Real hu = 1e-7 * std::max(Real(1), s.umax - s.umin);
    const Real hv = 1e-7 * std::max(Real(1), s.vmax - s.vmin);
    Real found = kInfinity;
    int tried = 0;
    for (const Candidate& c0 : candidates) {
        if (c0.t > found + 1e-3 || ++tried > 48) break;
        Real u = c0.u, v = c0.v, t = c0.t;
        bool converged = false;
        for (int it = 0; it < 40 && !converged; ++it) {
            const Point3 p = f.point(u, v);
            const Vector3 res = p - (o + d * t);
            const Vector3 su = (f.point(u + hu, v) - f.point(u - hu, v)) * (0.5 / hu);
            const Vector3 sv = (f.point(u, v + hv) - f.point(u, v - hv)) * (0.5 / hv);
            // Solve [su sv -d] (du, dv, dt) = -res by Cramer's rule.
            const Vector3 nd = d * -1.0;
            const Real det = dot(su, cross(sv, nd));
            if (det == 0 || !std::isfinite(det)) break;
            const Vector3 rhs = res * -1.0;
            const Real du = dot(rhs, cross(sv, nd)) / det;
            const Real dv = dot(su, cross(rhs, nd)) / det;
            const Real dt = dot(su, cross(sv, rhs)) / det;
            u += du;
            v += dv;
            t += dt;
            converged = std::fabs(dt) <= 1e-13 * std::max(Real(1), std::fabs(t)) &&
                        std::fabs(du) <= 1e-12 && std::fabs(dv) <= 1e-12;
        }
        if (!converged) continue;
        const Real slack_u = 1e-9 * (s.umax - s.umin), slack_v = 1e-9 * (s.vmax - s.vmin);
        if (u < s.umin - slack_u || u > s.umax + slack_u || v < s.vmin - slack_v ||
            v > s.vmax + slack_v)
            continue;
        if (t < t_in || t > t_out) continue;
        if (HP(t) < best.floor) continue;
        found = std::min(found, t);
    }
    if (found < kInfinity) best.offer(HP(found), 0);
    return true;
}

}  // namespace povwall::trace
