#include "trace/shapes/julia_fractal.h"

#include <cmath>
#include <vector>

#include "core/math_constants.h"
#include "trace/shapes/julia_complex.h"

namespace povwall::trace {
namespace {

constexpr Real kFractalTolerance = 1e-7;  // marching, bisection and bound (FT)
constexpr Real kHyperTolerance = 1e-8;    // the hypercomplex distance estimate (FTh)

using Q = Quad;

// exp ... atanh and pwr: the hypercomplex functions built from complex ones.
bool is_function_family(const JuliaFractal& j) {
    return j.algebra == JuliaFractal::Algebra::Hypercomplex &&
           j.function >= JuliaFractal::Function::Exp;
}

Real norm2(const Q& q) { return q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]; }

// q -> f(q) + c.
Q step(const JuliaFractal& j, const Q& q) {
    const Real x = q[0], y = q[1], z = q[2], w = q[3];
    Q r;
    if (j.algebra == JuliaFractal::Algebra::Quaternion) {
        if (j.function == JuliaFractal::Function::Cube) {
            const Real d = y * y + z * z + w * w, k = 3 * x * x - d;
            r = {x * (x * x - 3 * d), y * k, z * k, w * k};
        } else {
            r = {x * x - (y * y + z * z + w * w), 2 * x * y, 2 * x * z, 2 * x * w};
        }
    } else if (is_function_family(j)) {
        r = hypercomplex_function(j, q);
    } else if (j.function == JuliaFractal::Function::Reciprocal) {
        const Real det = ((x - w) * (x - w) + (y + z) * (y + z)) *
                         ((x + w) * (x + w) + (y - z) * (y - z));
        if (det == 0) {
            r = q;  // POV-Ray leaves the value undefined there; keep the point
        } else {
            const Real m = x * x + y * y + z * z + w * w, k = x * w - y * z;
            r = {(x * m - 2 * w * k) / det, (-y * m - 2 * z * k) / det,
                 (-z * m - 2 * y * k) / det, (w * m - 2 * x * k) / det};
        }
    } else {
        // Hypercomplex square (POV-Ray's cube iterates the square too).
        r = {x * x + w * w - y * y - z * z, 2 * (x * y - z * w), 2 * (x * z - w * y),
             2 * (x * w + y * z)};
    }
    for (int k = 0; k < 4; ++k) r[k] += j.c[k];
    return r;
}

// The 4-D starting point of (x, y, z) on the slice.
Q start(const JuliaFractal& j, const Point3& p) {
    const Q& s = j.slice;
    return {p.x, p.y, p.z,
            (j.slice_distance - s[0] * p.x - s[1] * p.y - s[2] * p.z) / s[3]};
}

struct Stack {
    std::vector<Q> q;
    void size_for(const JuliaFractal& j) {
        if (q.size() < size_t(j.max_iteration) + 1) q.resize(size_t(j.max_iteration) + 1);
    }
};

// The plain iteration: inside when it never escapes. Fills the stack. For the function
// family POV-Ray starts it from (x, y, y) (its Iteration_HCompl_Func reads y for z), so
// the bisection and the inside test see another set than the march: replicated.
bool iterate(const JuliaFractal& j, const Point3& p, Stack& st) {
    st.q[0] = start(j, is_function_family(j) ? Point3{p.x, p.y, p.y} : p);
    for (int i = 1; i <= j.max_iteration; ++i) {
        if (norm2(st.q[size_t(i - 1)]) > j.exit_value) return false;
        st.q[size_t(i)] = step(j, st.q[size_t(i - 1)]);
    }
    return true;
}

Q hyper_product(const Q& p, const Q& r) {
    return {p[0] * r[0] - p[1] * r[1] - p[2] * r[2] + p[3] * r[3],
            p[1] * r[0] + p[0] * r[1] - p[3] * r[2] - p[2] * r[3],
            p[2] * r[0] - p[3] * r[1] + p[0] * r[2] - p[1] * r[3],
            p[3] * r[0] + p[2] * r[1] + p[1] * r[2] + p[0] * r[3]};
}

Q hyper_square(const Q& q) {
    const Real x = q[0], y = q[1], z = q[2], w = q[3];
    return {x * x - y * y - z * z + w * w, 2 * (x * y - z * w), 2 * (z * x - w * y),
            2 * (w * x + z * y)};
}

// The hypercomplex gradient from the first n + 1 stack entries.
Vector3 hyper_normal(const JuliaFractal& j, const Stack& st, int n) {
    Q v = st.q[0];
    for (int i = 1; i < n; ++i) {
        const Q& qi = st.q[size_t(i)];
        if (j.function == JuliaFractal::Function::Reciprocal) {
            // -(1/q)^2, applied on the right
            JuliaFractal plain = j;
            plain.c = {0, 0, 0, 0};
            Q h = hyper_square(step(plain, qi));
            for (Real& k : h) k = -k;
            v = hyper_product(v, h);
        } else if (is_function_family(j)) {
            // f(q_i), not its derivative, as POV-Ray's Normal_Calc_HCompl_Func
            v = hyper_product(hypercomplex_function(j, qi), v);
        } else {
            v = hyper_product(qi, v);
        }
    }
    Q q = st.q[size_t(n)];
    if (j.function == JuliaFractal::Function::Sqr) {
        const Real f = std::pow(2.0, std::max(n, 1));
        for (Real& k : q) k *= f;
    }
    return {v[0] * q[0] + v[1] * q[1] + v[2] * q[2] + v[3] * q[3],
            -v[1] * q[0] + v[0] * q[1] - v[3] * q[2] + v[2] * q[3],
            -v[2] * q[0] - v[3] * q[1] + v[0] * q[2] + v[1] * q[3]};
}

// The normal at a point whose iteration fills the whole stack.
Vector3 normal_from(const JuliaFractal& j, const Stack& st) {
    const int n = j.max_iteration;
    if (j.algebra == JuliaFractal::Algebra::Hypercomplex) return hyper_normal(j, st, n);
    Q g[3] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};
    const bool cube = j.function == JuliaFractal::Function::Cube;
    for (int i = 1; i <= n; ++i) {
        const Q& q = st.q[size_t(i - 1)];
        const Real x = q[0], y = q[1], z = q[2], w = q[3];
        for (Q& v : g) {
            const Real a = v[0], b = v[1], c = v[2], d = v[3];
            if (cube) {
                const Real dd = y * y + z * z + w * w;
                const Real x3 = x * x - dd, x4 = 3 * x * x - dd;
                const Real t = 2 * (b * y + c * z + d * w), t2 = 6 * x * a - t;
                v = {3 * (a * x3 - x * t), b * x4 + y * t2, c * x4 + z * t2,
                     d * x4 + w * t2};
            } else {
                v = {a * x - b * y - c * z - d * w, a * y + x * b, a * z + x * c,
                     a * w + x * d};
            }
        }
    }
    const Q& q = st.q[size_t(n)];
    auto dot4 = [&](const Q& v) {
        return v[0] * q[0] + v[1] * q[1] + v[2] * q[2] + v[3] * q[3];
    };
    return {dot4(g[0]), dot4(g[1]), dot4(g[2])};
}

// The iteration with a distance estimate: inside (distance = the step), or outside with
// how far the surface at least is.
bool estimate(const JuliaFractal& j, const Point3& p, const Vector3& dir, Stack& st,
              Real& dist) {
    st.q[0] = start(j, p);
    int escaped = 0;
    for (int i = 1; i <= j.max_iteration; ++i) {
        if (norm2(st.q[size_t(i - 1)]) > j.exit_value) {
            escaped = i;
            break;
        }
        st.q[size_t(i)] = step(j, st.q[size_t(i - 1)]);
    }
    if (escaped == 0) {
        dist = j.precision;
        return true;
    }
    const int i = escaped;
    const Real f = norm2(st.q[size_t(i - 1)]);
    if (j.algebra == JuliaFractal::Algebra::Quaternion) {
        Q prod = st.q[0];
        for (int k = 1; k <= i - 1; ++k) {
            const Q& b = st.q[size_t(k)];
            const Q a = prod;
            prod = {a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
                    a[0] * b[1] + a[1] * b[0] - a[2] * b[3] + a[3] * b[2],
                    a[0] * b[2] + a[1] * b[3] + a[2] * b[0] - a[3] * b[1],
                    a[0] * b[3] - a[1] * b[2] + a[2] * b[1] + a[3] * b[0]};
        }
        const Real k = j.function == JuliaFractal::Function::Cube ? 3 : 2;
        dist = std::pow(k, -i) * std::sqrt(f / norm2(prod)) * std::log(f);
        return false;
    }
    const Vector3 g = hyper_normal(j, st, i - 1);
    const Real sigma = dot(g, dir);
    dist = j.precision;
    if (sigma < -kHyperTolerance) {
        const Real s2 = -2 * sigma;
        if (j.precision * s2 < f && f < 30 * j.precision * s2) dist = f / s2;
    }
    return false;
}

}  // namespace

bool julia_inside(const JuliaFractal& j, const Point3& p) {
    thread_local Stack st;
    st.size_for(j);
    return iterate(j, p, st);
}

void shape_hits(const JuliaFractal& j, const LocalRay& r, ShapeHits& out) {
    thread_local Stack st;
    st.size_for(j);
    // POV-Ray uses the world ray as it is when the object has no transform.
    const Vector3 d = r.transformed ? r.unit : r.direction;
    const Real to_world = r.transformed ? 1 / r.length : 1;
    // Outside CSG POV-Ray reports the first hit only: a shadow ray it restarted past a
    // see-through surface marches afresh from there (and so meets the far side).
    const Real t0 = !r.csg_child && r.restart > 0 ? r.restart / to_world : 0;
    const Point3 o = r.origin + d * t0;
    // The bounding sphere (POV-Ray's sphere test).
    const Vector3 v = Point3{0, 0, 0} - o;
    const Real l = dot(v, v), b = dot(v, d);
    if (l >= j.radius2 && b < kPovEpsilon) return;
    const Real h2 = j.radius2 - l + b * b;
    if (!(h2 > kPovEpsilon)) return;
    const Real h = std::sqrt(h2);
    const Real t_far = b + h;
    if (t_far < kFractalTolerance) return;
    Real t = std::max(b - h, kFractalTolerance);

    Point3 x = o + d * t;
    Real dist, next_dist = 0;
    bool cur = estimate(j, x, d, st, dist);
    if (cur) {
        x = x + d * (2 * kFractalTolerance);
        t += 2 * kFractalTolerance;
        if (t > t_far) return;
        cur = estimate(j, x, d, st, dist);
    }
    bool last = false;
    while (t < t_far) {
        Point3 p = x;
        bool next = cur;
        for (;;) {  // march with the estimate, at least a precision step at a time
            dist = std::max(dist, j.precision);
            t += dist;
            if (t > t_far) return;
            p = x;
            x = x + d * dist;
            next = estimate(j, x, d, st, next_dist);
            if (next != cur) {
                t -= dist;
                break;
            }
            dist = next_dist;
        }
        while (dist > kFractalTolerance) {  // bisect down to the tolerance
            dist /= 2;
            const Point3 m = p + d * dist;
            last = iterate(j, m, st);
            if (last == cur) {
                p = m;
                t += dist;
                if (t > t_far) return;
            }
        }
        if (!cur) {
            p = p + d * dist;
            t += dist;
            iterate(j, p, st);
        } else if (last != cur) {
            iterate(j, p, st);
        }
        out.push_back({(t0 + t) * to_world, p, 0, 0, 0, normal_from(j, st), true});
        if (!r.csg_child) return;  // POV-Ray stops at its first hit outside CSG
        dist = next_dist;
        cur = next;
    }
}

Vector3 shape_normal(const JuliaFractal&, const ShapeHit& h) { return h.normal; }

bool shape_inside(const JuliaFractal& j, const Point3& p) { return julia_inside(j, p); }

Bounds3 shape_bounds(const JuliaFractal& j) {
    const Real r = std::sqrt(j.radius2);
    return {Vector3(-r), Vector3(r)};
}

PovBBox shape_pov_bbox(const JuliaFractal& j, const CompactTransform& xf) {
    return pov_transformed_bbox(shape_bounds(j), xf);
}

bool shape_oracle_first(const JuliaFractal&, const OracleRay&, OracleBest&) {
    return false;
}

}  // namespace povwall::trace
