#include "trace/shapes/poly.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <vector>

#include "core/pov_polysolve.h"
#include "trace/roots_sturm.h"
#include "trace/shapes/oracle_math.h"
#include "trace/shapes/sort_hits.h"

namespace povwall::trace {
namespace {

// Binomial coefficients C(n, k) for n <= kPolyMaxOrder, exact in double (the largest,
// C(35, 17), needs 33 bits).
using BinomialTable = std::array<std::array<Real, kPolyMaxOrder + 1>, kPolyMaxOrder + 1>;
constexpr BinomialTable make_binomials() {
    BinomialTable c{};
    for (int n = 0; n <= kPolyMaxOrder; ++n) {
        c[n][0] = c[n][n] = 1;
        for (int k = 1; k < n; ++k) c[n][k] = c[n - 1][k - 1] + c[n - 1][k];
    }
    return c;
}
constexpr BinomialTable kBinomial = make_binomials();

// base^0 .. base^n, each power the base times the previous one (POV-Ray's order).
template <class T>
void powers(const T& base, int n, T* out) {
    out[0] = 1;
    if (n >= 1) out[1] = base;
    for (int k = 2; k <= n; ++k) out[k] = base * out[k - 1];
}

// The coefficients of t^(e-h), h = 0..e, in (p + t d)^e: (C(e, h) d^(e-h)) p^h.
template <class T>
void binomial_factor(int e, const T* p_pow, const T* d_pow, T* out) {
    for (int h = 0; h <= e; ++h) out[h] = (T(kBinomial[e][h]) * d_pow[e - h]) * p_pow[h];
}

// POV-Ray's order-2 poly: its own quadratic along the unit direction (no solver).
int quadratic_roots(const Real* a, const Point3& p, const Vector3& d, Real* roots) {
    const Real x = p.x, y = p.y, z = p.z, u = d.x, v = d.y, w = d.z;
    const Real x2 = x * x, y2 = y * y, z2 = z * z;
    const Real uu = u * u, vv = v * v, ww = w * w;
    const Real alpha = a[0] * uu + (a[1] * u) * v + (a[2] * u) * w + a[4] * vv +
                       (a[5] * v) * w + a[7] * ww;
    const Real beta = ((2 * a[0]) * x) * u + a[1] * (x * v + u * y) +
                      a[2] * (x * w + u * z) + a[3] * u + ((2 * a[4]) * y) * v +
                      a[5] * (y * w + v * z) + a[6] * v + ((2 * a[7]) * z) * w + a[8] * w;
    const Real gamma = a[0] * x2 + (a[1] * x) * y + (a[2] * x) * z + a[3] * x +
                       a[4] * y2 + (a[5] * y) * z + a[6] * y + a[7] * z2 + a[8] * z +
                       a[9];
    if (std::fabs(alpha) < 1e-20) {  // POV-Ray's COEFF_LIMIT
        if (std::fabs(beta) < 1e-20) return 0;
        roots[0] = -gamma / beta;
        return 1;
    }
    const Real disc = beta * beta - (4 * alpha) * gamma;
    if (disc < 0) return 0;
    const Real s = std::sqrt(disc);
    roots[0] = (-beta + s) / (2 * alpha);
    roots[1] = (-beta - s) / (2 * alpha);
    return 2;
}

}  // namespace

int poly_roots(const Poly& s, const Point3& p, const Vector3& d, Real* roots) {
    const int n = s.order;
    if (n == 2) return quadratic_roots(s.coeffs.data(), p, d, roots);
    Real px[kPolyMaxOrder + 1], py[kPolyMaxOrder + 1], pz[kPolyMaxOrder + 1];
    Real dx[kPolyMaxOrder + 1], dy[kPolyMaxOrder + 1], dz[kPolyMaxOrder + 1];
    powers(p.x, n, px), powers(p.y, n, py), powers(p.z, n, pz);
    powers(d.x, n, dx), powers(d.y, n, dy), powers(d.z, n, dz);
    // eqn[m] multiplies t^(n-m).
    Real eqn[kPolyMaxOrder + 1] = {};
    Real tx[kPolyMaxOrder + 1], ty[kPolyMaxOrder + 1], tz[kPolyMaxOrder + 1];
    const Real* c = s.coeffs.data();
    for (int i = n; i >= 0; --i) {
        binomial_factor(i, px, dx, tx);
        for (int j = n - i; j >= 0; --j) {
            binomial_factor(j, py, dy, ty);
            for (int k = n - i - j; k >= 0; --k) {
                const Real coeff = *c++;
                if (coeff == 0) continue;
                binomial_factor(k, pz, dz, tz);
                const int offset = n - (i + j + k);
                for (int i1 = 0; i1 <= i; ++i1)
                    for (int j1 = 0; j1 <= j; ++j1)
                        for (int k1 = 0; k1 <= k; ++k1)
                            eqn[offset + i1 + j1 + k1] +=
                                ((coeff * tx[i1]) * ty[j1]) * tz[k1];
            }
        }
    }
    // Leading coefficients exactly 0 drop out; degree 1 or less is no hit at all (POV-Ray
    // never solves it, so a cubic x^3 + y seen straight along y is invisible).
    int skip = 0;
    while (skip <= n && eqn[skip] == 0) ++skip;
    const int m = n - skip;
    if (m <= 1) return 0;
    return pov_solve_polynomial(m, eqn + skip, roots, s.sturm, kPolyDepthTolerance);
}

Real poly_value(const Poly& s, const Point3& p) {
    const int n = s.order;
    Real x[kPolyMaxOrder + 1], y[kPolyMaxOrder + 1], z[kPolyMaxOrder + 1];
    powers(p.x, n, x), powers(p.y, n, y), powers(p.z, n, z);
    Real f = 0;
    const Real* c = s.coeffs.data();
    for (int i = n; i >= 0; --i)
        for (int j = n - i; j >= 0; --j)
            for (int k = n - i - j; k >= 0; --k) {
                const Real coeff = *c++;
                if (coeff != 0) f += ((coeff * x[i]) * y[j]) * z[k];
            }
    return f;
}

Vector3 poly_gradient(const Poly& s, const Point3& q) {
    const Real* a = s.coeffs.data();
    const Real x = q.x, y = q.y, z = q.z;
    // Orders 2 to 4: POV-Ray's hand-expanded gradients (normal1), grouped as its code
    // (integer factors multiply first; sums run left to right).
    if (s.order == 2) {
        return {2 * a[0] * x + a[1] * y + a[2] * z + a[3],
                a[1] * x + 2 * a[4] * y + a[5] * z + a[6],
                a[2] * x + a[5] * y + 2 * a[7] * z + a[8]};
    }
    const Real x2 = x * x, y2 = y * y, z2 = z * z;
    if (s.order == 3) {
        return {3 * a[0] * x2 + 2 * x * (a[1] * y + a[2] * z + a[3]) + a[4] * y2 +
                    y * (a[5] * z + a[6]) + a[7] * z2 + a[8] * z + a[9],
                a[1] * x2 + x * (2 * a[4] * y + a[5] * z + a[6]) + 3 * a[10] * y2 +
                    2 * y * (a[11] * z + a[12]) + a[13] * z2 + a[14] * z + a[15],
                a[2] * x2 + x * (a[5] * y + 2 * a[7] * z + a[8]) + a[11] * y2 +
                    y * (2 * a[13] * z + a[14]) + 3 * a[16] * z2 + 2 * a[17] * z + a[18]};
    }
    if (s.order == 4) {
        const Real x3 = x * x2, y3 = y * y2, z3 = z * z2;
        return {
            4 * a[0] * x3 + 3 * x2 * (a[1] * y + a[2] * z + a[3]) +
                2 * x *
                    (a[4] * y2 + y * (a[5] * z + a[6]) + a[7] * z2 + a[8] * z + a[9]) +
                a[10] * y3 + y2 * (a[11] * z + a[12]) +
                y * (a[13] * z2 + a[14] * z + a[15]) + a[16] * z3 + a[17] * z2 +
                a[18] * z + a[19],
            a[1] * x3 + x2 * (2 * a[4] * y + a[5] * z + a[6]) +
                x * (3 * a[10] * y2 + 2 * y * (a[11] * z + a[12]) + a[13] * z2 +
                     a[14] * z + a[15]) +
                4 * a[20] * y3 + 3 * y2 * (a[21] * z + a[22]) +
                2 * y * (a[23] * z2 + a[24] * z + a[25]) + a[26] * z3 + a[27] * z2 +
                a[28] * z + a[29],
            a[2] * x3 + x2 * (a[5] * y + 2 * a[7] * z + a[8]) +
                x * (a[11] * y2 + y * (2 * a[13] * z + a[14]) + 3 * a[16] * z2 +
                     2 * a[17] * z + a[18]) +
                a[21] * y3 + y2 * (2 * a[23] * z + a[24]) +
                y * (3 * a[26] * z2 + 2 * a[27] * z + a[28]) + 4 * a[30] * z3 +
                3 * a[31] * z2 + 2 * a[32] * z + a[33]};
    }
    // Higher orders: term by term (normal0), zero coefficients included.
    const int n = s.order;
    Real xp[kPolyMaxOrder + 1], yp[kPolyMaxOrder + 1], zp[kPolyMaxOrder + 1];
    powers(x, n, xp), powers(y, n, yp), powers(z, n, zp);
    Vector3 g{0, 0, 0};
    for (int i = n; i >= 0; --i)
        for (int j = n - i; j >= 0; --j)
            for (int k = n - i - j; k >= 0; --k) {
                const Real c = *a++;
                if (i >= 1) g.x += (i * c) * ((xp[i - 1] * yp[j]) * zp[k]);
                if (j >= 1) g.y += (j * c) * ((xp[i] * yp[j - 1]) * zp[k]);
                if (k >= 1) g.z += (k * c) * ((xp[i] * yp[j]) * zp[k - 1]);
            }
    return g;
}

void shape_hits(const Poly& s, const LocalRay& r, ShapeHits& out) {
    Real roots[kPolyMaxOrder];
    const int n = poly_roots(s, r.origin, r.unit, roots);
    const size_t first = out.size();
    for (int k = 0; k < n; ++k) {
        const Real t = roots[k];
        if (!(t > kPolyDepthTolerance)) continue;
        // A root equal to any earlier one (kept or not) is pushed once.
        if (std::find(roots, roots + k, t) != roots + k) continue;
        ShapeHit h{t / r.length, r.origin + r.unit * t, 0};
        // POV-Ray's hit point is this object point mapped forward, not the ray's point.
        h.own_point = true;
        out.push_back(h);
    }
    stable_sort_by_depth(out, first);
}

Vector3 shape_normal(const Poly& s, const ShapeHit& h) {
    const Vector3 g = poly_gradient(s, h.p);
    // POV-Ray's normal where the gradient vanishes.
    if (!(dot(g, g) > 0)) return {1, 0, 0};
    return g;
}

bool shape_inside(const Poly& s, const Point3& p) {
    return poly_value(s, p) < kPolyInsideTolerance;
}

Bounds3 shape_bounds(const Poly&) { return Bounds3::everything(); }

PovBBox shape_pov_bbox(const Poly&, const CompactTransform&) {
    return pov_infinite_bbox();
}

bool shape_oracle_first(const Poly& s, const OracleRay& r, OracleBest& best) {
    // F along o + t d (|d| = 1) expanded in 50 digits: sum over the terms of
    // c (ox + t dx)^i (oy + t dy)^j (oz + t dz)^k.
    const int n = s.order;
    std::vector<HP> ox(n + 1), oy(n + 1), oz(n + 1), dx(n + 1), dy(n + 1), dz(n + 1);
    powers(r.o.x, n, ox.data()), powers(r.o.y, n, oy.data()), powers(r.o.z, n, oz.data());
    powers(r.d.x, n, dx.data()), powers(r.d.y, n, dy.data()), powers(r.d.z, n, dz.data());
    std::vector<HP> tx(n + 1), ty(n + 1), tz(n + 1);
    auto p = std::make_unique<SturmPoly<HP, kPolyMaxOrder>>();
    for (int e = 0; e <= n; ++e) p->c[e] = 0;  // c[e]: coefficient of t^e
    const Real* c = s.coeffs.data();
    for (int i = n; i >= 0; --i) {
        binomial_factor(i, ox.data(), dx.data(), tx.data());
        for (int j = n - i; j >= 0; --j) {
            binomial_factor(j, oy.data(), dy.data(), ty.data());
            for (int k = n - i - j; k >= 0; --k) {
                const Real coeff = *c++;
                if (coeff == 0) continue;
                binomial_factor(k, oz.data(), dz.data(), tz.data());
                for (int i1 = 0; i1 <= i; ++i1)
                    for (int j1 = 0; j1 <= j; ++j1)
                        for (int k1 = 0; k1 <= k; ++k1)
                            p->c[(i - i1) + (j - j1) + (k - k1)] +=
                                HP(coeff) * tx[i1] * ty[j1] * tz[k1];
            }
        }
    }
    p->degree = n;
    while (p->degree >= 0 && p->c[p->degree] == 0) --p->degree;
    if (p->degree <= 1) return true;  // POV-Ray: no hit
    std::vector<HP> roots(size_t(p->degree));
    const int found =
        sturm_real_roots(*p, HP(0), HP(kMaxDistance), roots.data(), p->degree);
    for (int k = 0; k < found; ++k) best.offer(roots[size_t(k)], kPolyDepthTolerance);
    return true;
}

}  // namespace povwall::trace
