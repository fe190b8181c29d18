#include "core/parametric.h"

#include <algorithm>
#include <cmath>

namespace povwall {
namespace {

// POV-Ray's Interval: the values at the two ends of an edge of length dx, widened so that
// a function with slope <= max_gradient stays inside (half the slack left after going
// from one value to the other).
void widen(Real dx, Real a, Real b, Real max_gradient, Real& lo, Real& hi) {
    const Real dy = std::fabs(a - b);
    Real offset = max_gradient * (dx - dy / max_gradient) / 2;
    if (offset < 0) offset = 0;
    hi = std::max(a, b) + offset;
    lo = std::min(a, b) - offset;
}

struct Precompute {
    const Parametric& p;
    const FunctionHooks& hooks;
    ParametricPrecompute& out;
    int first_leaf;

    void sector(int s, Real u0, Real v0, Real u1, Real v1) {
        if (s >= first_leaf) {
            for (int a = 0; a < 3; ++a) {
                if (!out.axis[a]) continue;
                parametric_interval(*p.functions[a], hooks, p.accuracy, p.max_gradient,
                                    u0, v0, u1, v1, out.low[a][size_t(s)],
                                    out.high[a][size_t(s)]);
            }
            return;
        }
        if (u1 - u0 < v1 - v0) {
            sector(2 * s, u0, v0, u1, (v0 + v1) / 2.0);
            sector(2 * s + 1, u0, (v0 + v1) / 2.0, u1, v1);
        } else {
            sector(2 * s, u0, v0, (u0 + u1) / 2.0, v1);
            sector(2 * s + 1, (u0 + u1) / 2.0, v0, u1, v1);
        }
        for (int a = 0; a < 3; ++a) {
            if (!out.axis[a]) continue;
            auto& lo = out.low[a];
            auto& hi = out.high[a];
            const size_t k = size_t(s), l = size_t(2 * s), r = size_t(2 * s + 1);
            hi[k] = hi[l] > hi[r] ? hi[l] : hi[r];
            lo[k] = lo[l] < lo[r] ? lo[l] : lo[r];
        }
    }
};

}  // namespace

Real parametric_coordinate(const FunctionProgram& f, const FunctionHooks& hooks, Real u,
                           Real v) {
    const double args[3] = {u, v, 0};
    return evaluate_function(f, args, hooks);
}

void parametric_interval(const FunctionProgram& f, const FunctionHooks& hooks,
                         Real accuracy, Real max_gradient, Real u0, Real v0, Real u1,
                         Real v1, Real& low, Real& high) {
    const Real f00 = parametric_coordinate(f, hooks, u0, v0) - accuracy;
    const Real f01 = parametric_coordinate(f, hooks, u0, v1) - accuracy;
    const Real f10 = parametric_coordinate(f, hooks, u1, v0) - accuracy;
    const Real f11 = parametric_coordinate(f, hooks, u1, v1) - accuracy;
    Real lo0, hi0, lo1, hi1, unused;
    widen(v1 - v0, f00, f01, max_gradient, lo0, hi0);  // the edge u = u0
    widen(v1 - v0, f10, f11, max_gradient, lo1, hi1);  // the edge u = u1
    // The two edges' extremes as if met at the same v: the worst case across u.
    widen(u1 - u0, hi0, hi1, max_gradient, unused, high);
    widen(u1 - u0, lo0, lo1, max_gradient, low, unused);
}

ParametricPrecompute make_parametric_precompute(const Parametric& p, const bool axis[3],
                                                int depth, const FunctionHooks& hooks) {
    ParametricPrecompute out;
    out.depth = depth;
    const size_t n = size_t(1) << depth;
    for (int a = 0; a < 3; ++a) {
        out.axis[a] = axis[a];
        if (!axis[a]) continue;
        out.low[a].assign(n, 0);
        out.high[a].assign(n, 0);
    }
    Precompute run{p, hooks, out, 1 << (depth - 1)};
    run.sector(1, p.umin, p.vmin, p.umax, p.vmax);
    return out;
}

}  // namespace povwall
