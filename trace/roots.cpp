#include "trace/roots.h"

#include <algorithm>
#include <cmath>

#include "trace/roots_sturm.h"

namespace povwall::trace {

int solve_quadratic(Real a, Real b, Real c, Real roots[2]) {
    if (a == 0) {
        if (b == 0) return 0;
        roots[0] = -c / b;
        return 1;
    }
    Real disc = b * b - 4 * a * c;
    if (disc < 0) return 0;
    Real s = std::sqrt(disc);
    // q has the sign of b, so neither root subtracts nearly equal numbers.
    Real q = -0.5 * (b + (b >= 0 ? s : -s));
    Real r0 = q / a, r1 = q != 0 ? c / q : r0;
    roots[0] = std::min(r0, r1);
    roots[1] = std::max(r0, r1);
    return 2;
}

int solve_quadratic_naive(Real a, Real b, Real c, Real roots[2]) {
    if (a == 0) {
        if (b == 0) return 0;
        roots[0] = -c / b;
        return 1;
    }
    Real disc = b * b - 4 * a * c;
    if (disc < 0) return 0;
    Real s = std::sqrt(disc);
    Real r0 = (-b - s) / (2 * a), r1 = (-b + s) / (2 * a);
    roots[0] = std::min(r0, r1);
    roots[1] = std::max(r0, r1);
    return 2;
}

namespace {

// Real roots of x^3 + a x^2 + b x + c; only the largest is used by Ferrari.
int solve_cubic_real(Real a, Real b, Real c, Real roots[3]) {
    Real q = (a * a - 3 * b) / 9, r = (2 * a * a * a - 9 * a * b + 27 * c) / 54;
    Real q3 = q * q * q;
    if (r * r < q3) {
        Real th = std::acos(std::clamp(r / std::sqrt(q3), -1.0, 1.0));
        Real s = -2 * std::sqrt(q);
        roots[0] = s * std::cos(th / 3) - a / 3;
        roots[1] = s * std::cos((th + 2 * kPi) / 3) - a / 3;
        roots[2] = s * std::cos((th - 2 * kPi) / 3) - a / 3;
        return 3;
    }
    Real big = -std::cbrt(std::fabs(r) + std::sqrt(r * r - q3));
    if (r < 0) big = -big;
    Real small = big != 0 ? q / big : 0;
    roots[0] = big + small - a / 3;
    return 1;
}

}  // namespace

int solve_cubic(Real a, Real b, Real c, Real roots[3]) {
    const Real q = (a * a - 3 * b) / 9, r = (2 * a * a * a - 9 * a * b + 27 * c) / 54;
    const Real q3 = q * q * q;
    if (q3 - r * r >= 0) {
        if (!(q3 > 0)) return 0;
        const Real th = std::acos(std::clamp(r / std::sqrt(q3), -1.0, 1.0)) / 3;
        const Real s = -2 * std::sqrt(q);
        roots[0] = s * std::cos(th) - a / 3;
        roots[1] = s * std::cos(th + 2 * kPi / 3) - a / 3;
        roots[2] = s * std::cos(th + 4 * kPi / 3) - a / 3;
        return 3;
    }
    Real big = std::cbrt(std::sqrt(r * r - q3) + std::fabs(r));
    const Real one = big + (big != 0 ? q / big : 0);
    roots[0] = (r < 0 ? one : -one) - a / 3;
    return 1;
}

namespace {

Real eval4(const Real c[5], Real x) {
    return (((c[4] * x + c[3]) * x + c[2]) * x + c[1]) * x + c[0];
}
Real deriv4(const Real c[5], Real x) {
    return ((4 * c[4] * x + 3 * c[3]) * x + 2 * c[2]) * x + c[1];
}

// p(x) with the rounding errors of Horner's scheme tracked by error-free transformations
// (TwoSum, and TwoProduct through fma) and added back: the residual as if evaluated in
// twice the working precision, which is what Newton needs beside a close root pair.
Real eval4_compensated(const Real c[5], Real x) {
    Real s = c[4], err = 0;
    for (int i = 3; i >= 0; --i) {
        const Real prod = s * x, prod_err = std::fma(s, x, -prod);
        const Real sum = prod + c[i], z = sum - prod;
        const Real sum_err = (prod - (sum - z)) + (c[i] - z);
        err = err * x + (prod_err + sum_err);
        s = sum;
    }
    return s + err;
}

}  // namespace

int solve_quartic_ferrari(const Real c_in[5], Real roots[4], QuarticPolish polish) {
    // Monic form, then the depressed quartic y^4 + p y^2 + q y + r with x = y - a/4.
    const Real a = c_in[3] / c_in[4], b = c_in[2] / c_in[4], cc = c_in[1] / c_in[4],
               d = c_in[0] / c_in[4];
    const Real a2 = a * a;
    const Real p = b - 3 * a2 / 8;
    const Real q = cc - a * b / 2 + a2 * a / 8;
    const Real r = d - a * cc / 4 + a2 * b / 16 - 3 * a2 * a2 / 256;
    int n = 0;
    Real ys[4];
    if (std::fabs(q) < 1e-14) {
        Real z[2];  // biquadratic in y^2
        int k = solve_quadratic(1, p, r, z);
        for (int i = 0; i < k; ++i) {
            if (z[i] >= 0) {
                Real s = std::sqrt(z[i]);
                ys[n++] = s;
                ys[n++] = -s;
            }
        }
    } else {
        // Resolvent cubic m^3 + p m^2 + (p^2/4 - r) m - q^2/8 = 0: its largest root is >
        // 0.
        Real m3[3];
        int k = solve_cubic_real(p, p * p / 4 - r, -q * q / 8, m3);
        Real m = m3[0];
        for (int i = 1; i < k; ++i) m = std::max(m, m3[i]);
        if (m <= 0) m = 1e-300;
        Real s = std::sqrt(2 * m);
        Real z[2];
        int k1 = solve_quadratic(1, s, p / 2 + m - q / (2 * s), z);
        for (int i = 0; i < k1; ++i) ys[n++] = z[i];
        int k2 = solve_quadratic(1, -s, p / 2 + m + q / (2 * s), z);
        for (int i = 0; i < k2; ++i) ys[n++] = z[i];
    }
    const Real mono[5] = {d, cc, b, a, 1};
    for (int i = 0; i < n; ++i) roots[i] = ys[i] - a / 4;
    std::sort(roots, roots + n);
    if (polish == QuarticPolish::None) return n;
    const bool compensated = polish == QuarticPolish::CompensatedNewton;
    auto residual = [&](Real x) {
        return compensated ? eval4_compensated(mono, x) : eval4(mono, x);
    };
    for (int i = 0; i < n; ++i) {
        // A polished root may not wander more than half way to its neighbours: beside a
        // close pair Newton could otherwise land on the other root and lose this one.
        Real reach = kInfinity;
        if (i > 0) reach = std::min(reach, 0.5 * (roots[i] - roots[i - 1]));
        if (i + 1 < n) reach = std::min(reach, 0.5 * (roots[i + 1] - roots[i]));
        const Real x0 = roots[i];
        Real x = x0, fx = residual(x);
        for (int it = 0; it < 8 && fx != 0; ++it) {
            const Real dfx = deriv4(mono, x);
            if (dfx == 0) break;
            const Real nx = x - fx / dfx;
            if (!std::isfinite(nx) || std::fabs(nx - x0) > reach) break;
            const Real fn = residual(nx);
            if (std::fabs(fn) >= std::fabs(fx)) break;
            x = nx;
            fx = fn;
        }
        roots[i] = x;
    }
    std::sort(roots, roots + n);
    return n;
}

int solve_quartic_sturm(const Real c[5], Real lo, Real hi, Real roots[4]) {
    SturmPoly<Real> p;
    p.degree = 4;
    // Monic: the remainder sequence's scale tests are relative to a leading 1.
    for (int i = 0; i < 5; ++i) p.c[i] = c[i] / c[4];
    return sturm_real_roots(p, lo, hi, roots, 4);
}

int solve_quartic(const Real c[5], Real lo, Real hi, Real roots[4]) {
    Real all[4];
    int n = solve_quartic_ferrari(c, all, QuarticPolish::Newton), k = 0;
    bool finite = true;
    for (int i = 0; i < n; ++i) finite = finite && std::isfinite(all[i]);
    // Real coefficients have an even number of real roots: an odd count (or a non-finite
    // root) means the closed form lost one to rounding, and Sturm counting settles it.
    if ((n & 1) || !finite) return solve_quartic_sturm(c, lo, hi, roots);
    for (int i = 0; i < n; ++i) {
        if (all[i] > lo && all[i] <= hi) roots[k++] = all[i];
    }
    return k;
}

}  // namespace povwall::trace
