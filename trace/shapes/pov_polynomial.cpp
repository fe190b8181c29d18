#include "trace/shapes/pov_polynomial.h"

#include <algorithm>
#include <cmath>

namespace povwall::trace {
namespace {

constexpr Real kSmallEnough = 1e-10;  // SMALL_ENOUGH: leading coefficients dropped
constexpr Real kZeroTolerance = 1e-10;
constexpr Real kMaxDistance = 1e7;  // the Sturm bracket's upper end
constexpr Real kRelError = 1e-12;
constexpr int kMaxIterations = 50;
constexpr Real kFudge = 1e12;  // FUDGE_FACTOR1: coefficients this far apart go to Sturm

// A polynomial in ascending powers: p[0] + p[1] x + ... + p[degree] x^degree.
struct Poly {
    int degree = 0;
    Real p[kPovMaxOrder + 1] = {};
    Real at(Real x) const {
        Real v = p[degree];
        for (int i = degree - 1; i >= 0; --i) v = v * x + p[i];
        return v;
    }
};

// Remainder of u divided by v (v's leading coefficient is +-1), small coefficients
// cleared from the top down; the remainder's degree drops over the cleared ones.
Poly remainder(const Poly& u, const Poly& v) {
    Poly r = u;
    if (v.degree > u.degree) return r;
    const Real lead = v.p[v.degree];
    for (int k = u.degree - v.degree; k >= 0; --k) {
        const Real q = r.p[v.degree + k] * lead;  // lead is +-1: q = r / lead
        for (int j = v.degree + k - 1; j >= k; --j) r.p[j] -= q * v.p[j - k];
    }
    int d = v.degree - 1;
    while (d > 0 && std::fabs(r.p[d]) < kSmallEnough) r.p[d--] = 0;
    r.degree = std::max(d, 0);
    for (int i = r.degree + 1; i <= u.degree; ++i) r.p[i] = 0;
    return r;
}

struct SturmSequence {
    Poly s[kPovMaxOrder + 1];
    int count = 0;

    explicit SturmSequence(const Poly& monic) {
        s[0] = monic;
        Poly& d = s[1];
        d.degree = monic.degree - 1;
        const Real f = 1 / std::fabs(monic.p[monic.degree] * monic.degree);
        for (int i = 1; i <= monic.degree; ++i) d.p[i - 1] = i * monic.p[i] * f;
        count = 2;
        while (s[count - 1].degree > 0 && count <= kPovMaxOrder) {
            Poly r = remainder(s[count - 2], s[count - 1]);
            if (r.degree == 0) {
                r.p[0] = -r.p[0];  // the last one is negated, not normalised
                s[count++] = r;
                break;
            }
            const Real scale = -std::fabs(r.p[r.degree]);
            for (int i = 0; i <= r.degree; ++i) r.p[i] /= scale;
            s[count++] = r;
        }
    }

    // Sign changes along the sequence at x (POV-Ray counts one after an exact zero too).
    int changes_at(Real x) const {
        int n = 0;
        Real last = s[0].at(x);
        for (int i = 1; i < count; ++i) {
            const Real v = s[i].at(x);
            if (last == 0 || last * v < 0) ++n;
            last = v;
        }
        return n;
    }
    int changes_at_zero() const {
        int n = 0;
        Real last = s[0].p[0];
        for (int i = 1; i < count; ++i) {
            const Real v = s[i].p[0];
            if (last == 0 || last * v < 0) ++n;
            last = v;
        }
        return n;
    }
    int changes_at_infinity() const {
        int n = 0;
        Real last = s[0].p[s[0].degree];
        for (int i = 1; i < count; ++i) {
            const Real v = s[i].p[s[i].degree];
            if (last == 0 || last * v < 0) ++n;
            last = v;
        }
        return n;
    }
};

bool converged(Real lo, Real hi, Real mid) {
    return std::fabs(mid) > kRelError ? std::fabs((hi - lo) / mid) < kRelError
                                      : std::fabs(hi - lo) < kRelError;
}

// Regula falsi with the Illinois modification on [a, b]: false when it does not settle.
bool regula_falsi(const Poly& p, Real a, Real b, Real& root) {
    Real fa = p.at(a), fb = p.at(b);
    if (fa * fb > 0) return false;
    if (std::fabs(fa) < kZeroTolerance) {
        root = a;
        return true;
    }
    if (std::fabs(fb) < kZeroTolerance) {
        root = b;
        return true;
    }
    Real last_fx = fa;
    for (int i = 0; i < kMaxIterations; ++i) {
        const Real x = (fb * a - fa * b) / (fb - fa);
        const Real fx = p.at(x);
        if (std::fabs(x) > kRelError ? std::fabs(fx / x) < kRelError
                                     : std::fabs(fx) < kRelError) {
            root = x;
            return true;
        }
        // The endpoint whose value has fx's sign moves to x; the other is kept, and its
        // value halved when fx kept its sign (Illinois).
        const bool move_a = fa < 0 ? fx < 0 : !(fx < 0);
        if (move_a) {
            a = x;
            fa = fx;
            if (last_fx * fx > 0) fb /= 2;
        } else {
            b = x;
            fb = fx;
            if (last_fx * fx > 0) fa /= 2;
        }
        last_fx = fx;
        if (std::fabs(b - a) < kRelError) {
            root = x;
            return true;
        }
    }
    return false;
}

// Roots in [lo, hi], where the sequence changes sign at_lo and at_hi times.
int bisect(const SturmSequence& seq, Real lo, Real hi, int at_lo, int at_hi,
           Real* roots) {
    if (at_lo - at_hi == 1 && regula_falsi(seq.s[0], lo, hi, roots[0])) return 1;
    Real mid = lo;
    for (int i = 0; i < kMaxIterations; ++i) {
        mid = (lo + hi) / 2;
        const int at_mid = seq.changes_at(mid);
        if (at_mid < at_hi || at_mid > at_lo) return 0;
        if (converged(lo, hi, mid)) {
            roots[0] = mid;
            return 1;
        }
        const int left = at_lo - at_mid, right = at_mid - at_hi;
        if (left > 0 && right > 0) {
            const int n = bisect(seq, lo, mid, at_lo, at_mid, roots);
            return n + bisect(seq, mid, hi, at_mid, at_hi, roots + n);
        }
        if (left == 0) {
            lo = mid;
            at_lo = at_mid;
        } else {
            hi = mid;
            at_hi = at_mid;
        }
    }
    roots[0] = mid;
    return 1;
}

// Coefficients (highest first) spanning more than 1e12, as POV-Ray judges it: the
// running largest is kept with its sign, so a negative one is replaced by the next.
bool difficult_coefficients(int n, const Real* c) {
    Real big = 0;
    for (int i = 0; i <= n; ++i) {
        if (std::fabs(c[i]) > big) big = c[i];
    }
    if (big == 0) return false;
    for (int i = 0; i <= n; ++i) {
        if (c[i] != 0 && std::fabs(big / c[i]) > kFudge) return true;
    }
    return false;
}

}  // namespace

int pov_sturm_roots(int n, const Real* c, Real* roots) {
    if (n < 1 || n > kPovMaxOrder || c[0] == 0) return 0;
    Poly monic;
    monic.degree = n;
    for (int i = 0; i <= n; ++i) monic.p[n - i] = c[i] / c[0];
    const SturmSequence seq(monic);
    const int at_zero = seq.changes_at_zero();
    if (at_zero == seq.changes_at_infinity()) return 0;
    const int at_max = seq.changes_at(kMaxDistance);
    if (at_zero - at_max <= 0) return 0;
    return bisect(seq, 0, kMaxDistance, at_zero, at_max, roots);
}

int pov_solve_quadratic(const Real c[3], Real roots[2]) {
    const Real a = c[0], b = c[1], k = c[2];
    if (a == 0) {
        if (b == 0) return 0;
        roots[0] = -k / b;
        return 1;
    }
    const Real B = -b / a, C = k / a;
    const Real d = B * B - 4 * C;
    if (d > -kSmallEnough && d < kSmallEnough) {
        roots[0] = B / 2;  // a grazing ray: one root
        return 1;
    }
    if (d < 0) return 0;
    const Real s = std::sqrt(d);
    roots[0] = (B + s) / 2;
    roots[1] = (B - s) / 2;
    return 2;
}

int pov_solve_cubic(const Real c[4], Real roots[3]) {
    if (c[0] == 0) return pov_solve_quadratic(c + 1, roots);
    const Real a1 = c[1] / c[0], a2 = c[2] / c[0], a3 = c[3] / c[0];
    const Real an = a1 / 3;
    const Real Q = (a1 * a1 - 3 * a2) / 9;
    const Real R = (a1 * (a1 * a1 - 4.5 * a2) + 13.5 * a3) / 27;
    const Real Q3 = Q * Q * Q, R2 = R * R;
    if (Q3 - R2 >= 0) {
        // Three real roots (a triple root, Q = 0, gives NaNs that no range test passes,
        // as in POV-Ray).
        const Real theta = std::acos(R / std::sqrt(Q3)) / 3;
        const Real s = -2 * std::sqrt(Q);
        roots[0] = s * std::cos(theta) - an;
        roots[1] = s * std::cos(theta + 2.0943951023931954923084) - an;
        roots[2] = s * std::cos(theta + 4.1887902047863909846168) - an;
        return 3;
    }
    const Real s = std::pow(std::sqrt(R2 - Q3) + std::fabs(R), 1.0 / 3.0);
    roots[0] = R < 0 ? (s + Q / s) - an : -(s + Q / s) - an;
    return 1;
}

int pov_solve_quartic(const Real c[5], Real roots[4]) {
    const Real c1 = c[1] / c[0], c2 = c[2] / c[0], c3 = c[3] / c[0], c4 = c[4] / c[0];
    // The depressed quartic y^4 + p y^2 + q y + r, x = y - c1 / 4.
    const Real c12 = c1 * c1;
    const Real p = c2 - 0.375 * c12;
    const Real q = 0.125 * c12 * c1 - 0.5 * c1 * c2 + c3;
    const Real r = -0.01171875 * c12 * c12 + 0.0625 * c12 * c2 - 0.25 * c1 * c3 + c4;
    // Its resolvent cubic; the first root found splits the quartic in two quadratics.
    const Real resolvent[4] = {1, -0.5 * p, -r, 0.5 * r * p - 0.125 * q * q};
    Real z3[3];
    if (pov_solve_cubic(resolvent, z3) == 0) return 0;
    const Real z = z3[0];
    Real d1 = 2 * z - p, d2;
    if (d1 < 0) {
        if (d1 > -kSmallEnough)
            d1 = 0;
        else
            return 0;
    }
    if (d1 < kSmallEnough) {
        d2 = z * z - r;
        if (d2 < 0) return 0;
        d2 = std::sqrt(d2);
    } else {
        d1 = std::sqrt(d1);
        d2 = 0.5 * q / d1;
    }
    const Real q1 = d1 * d1, q2 = -0.25 * c1;
    int n = 0;
    // POV-Ray's single-root branches subtract the shift the two-root ones add.
    Real disc = q1 - 4 * (z - d2);
    if (disc == 0) {
        roots[n++] = -0.5 * d1 - q2;
    } else if (disc > 0) {
        disc = std::sqrt(disc);
        roots[n++] = -0.5 * (d1 + disc) + q2;
        roots[n++] = -0.5 * (d1 - disc) + q2;
    }
    disc = q1 - 4 * (z + d2);
    if (disc == 0) {
        roots[n++] = 0.5 * d1 - q2;
    } else if (disc > 0) {
        disc = std::sqrt(disc);
        roots[n++] = 0.5 * (d1 + disc) + q2;
        roots[n++] = 0.5 * (d1 - disc) + q2;
    }
    return n;
}

int pov_solve_polynomial(int n, const Real* c, Real* roots, bool sturm, Real eps) {
    int i = 0;
    while (i < n && std::fabs(c[i]) < kSmallEnough) ++i;
    const Real* k = c + i;
    const int m = n - i;
    switch (m) {
        case 0:
            return 0;
        case 1:
            if (k[0] == 0) return 0;
            roots[0] = -k[1] / k[0];
            return 1;
        case 2:
            return pov_solve_quadratic(k, roots);
        case 3:
            if (eps > 0 && k[2] != 0 && std::fabs(k[3] / k[2]) < eps)
                return pov_solve_quadratic(k, roots);
            return sturm ? pov_sturm_roots(3, k, roots) : pov_solve_cubic(k, roots);
        case 4:
            if (eps > 0 && k[3] != 0 && std::fabs(k[4] / k[3]) < eps)
                return sturm ? pov_sturm_roots(3, k, roots) : pov_solve_cubic(k, roots);
            if (sturm || difficult_coefficients(4, k))
                return pov_sturm_roots(4, k, roots);
            return pov_solve_quartic(k, roots);
        default:
            return pov_sturm_roots(m, k, roots);
    }
}

}  // namespace povwall::trace
