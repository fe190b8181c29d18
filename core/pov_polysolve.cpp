#include "core/pov_polysolve.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

namespace povwall {

namespace {

constexpr Real kSmallEnough = 1e-10;  // a coefficient or discriminant this small is 0
constexpr Real kRelError = 1e-12;     // Sturm bisection and regula falsi convergence
constexpr int kMaxIterations = 50;
constexpr Real kBracketEnd = 1e7;       // MAX_DISTANCE: Sturm searches [0, 1e7]
constexpr Real kDifficultRatio = 1e12;  // coefficient spread that forces Sturm

// a x^2 + b x + c (x[0..2]). A discriminant within 1e-10 of 0 gives one root.
int quadratic(const Real* x, Real* y) {
    Real a = x[0], b = -x[1], c = x[2];
    if (a == 0) {
        if (b == 0) return 0;
        y[0] = c / b;
        return 1;
    }
    b /= a;
    c /= a;
    Real d = b * b - 4.0 * c;
    if (d > -kSmallEnough && d < kSmallEnough) {
        y[0] = 0.5 * b;
        return 1;
    }
    if (d < 0) return 0;
    d = std::sqrt(d);
    y[0] = (b + d) / 2;
    y[1] = (b - d) / 2;
    return 2;
}

// x[0] t^3 + ... (x[0..3]): trigonometric form for three real roots, else Cardano. A
// triple root (Q = 0) gives 0/0 = NaN, as in POV-Ray; NaN roots fail every range test.
int cubic(const Real* x, Real* y) {
    const Real a0 = x[0];
    if (a0 == 0) return quadratic(x + 1, y);
    Real a1 = x[1], a2 = x[2], a3 = x[3];
    if (a0 != 1) {
        a1 = x[1] / a0;
        a2 = x[2] / a0;
        a3 = x[3] / a0;
    }
    const Real a1_2 = a1 * a1;
    const Real q = (a1_2 - 3.0 * a2) / 9.0;
    const Real r = (a1 * (a1_2 - 4.5 * a2) + 13.5 * a3) / 27.0;
    const Real q3 = q * q * q, r2 = r * r;
    const Real shift = a1 / 3.0;
    if (q3 - r2 >= 0) {
        const Real theta = std::acos(r / std::sqrt(q3)) / 3.0;
        const Real s = -2.0 * std::sqrt(q);
        y[0] = s * std::cos(theta) - shift;
        y[1] = s * std::cos(theta + 2.0943951023931954923084) - shift;
        y[2] = s * std::cos(theta + 4.1887902047863909846168) - shift;
        return 3;
    }
    const Real s = std::pow(std::sqrt(r2 - q3) + std::fabs(r), 1.0 / 3.0);
    y[0] = r < 0 ? (s + q / s) - shift : -(s + q / s) - shift;
    return 1;
}

// The quartic x[0..4] through the depressed form and its resolvent cubic (POV-Ray's
// compiled "Vieta" variant, with its sign asymmetry in the single-root factors).
int quartic(const Real* x, Real* out) {
    Real c1 = x[1], c2 = x[2], c3 = x[3], c4 = x[4];
    if (x[0] != 1) {
        c1 = x[1] / x[0];
        c2 = x[2] / x[0];
        c3 = x[3] / x[0];
        c4 = x[4] / x[0];
    }
    const Real c1_2 = c1 * c1;
    Real p = -0.375 * c1_2 + c2;
    const Real q = 0.125 * c1_2 * c1 - 0.5 * c1 * c2 + c3;
    const Real r = -0.01171875 * c1_2 * c1_2 + 0.0625 * c1_2 * c2 - 0.25 * c1 * c3 + c4;
    const Real resolvent[4] = {1.0, -0.5 * p, -r, 0.5 * r * p - 0.125 * q * q};
    Real zs[3];
    if (cubic(resolvent, zs) == 0) return 0;
    const Real z = zs[0];
    Real d1 = 2.0 * z - p, d2;
    if (d1 < 0) {
        if (!(d1 > -kSmallEnough)) return 0;
        d1 = 0;
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
    p = q1 - 4.0 * (z - d2);
    if (p == 0) {
        out[n++] = -0.5 * d1 - q2;
    } else if (p > 0) {
        p = std::sqrt(p);
        out[n++] = -0.5 * (d1 + p) + q2;
        out[n++] = -0.5 * (d1 - p) + q2;
    }
    p = q1 - 4.0 * (z + d2);
    if (p == 0) {
        out[n++] = 0.5 * d1 - q2;
    } else if (p > 0) {
        p = std::sqrt(p);
        out[n++] = 0.5 * (d1 + p) + q2;
        out[n++] = 0.5 * (d1 - p) + q2;
    }
    return n;
}

// Whether the quartic's coefficients spread over more than 1e12. As POV-Ray, the
// largest is tracked by magnitude but stored signed: once it is negative, any later
// coefficient replaces it.
bool difficult(const Real* x) {
    Real big = 0;
    for (int i = 0; i <= 4; ++i)
        if (std::fabs(x[i]) > big) big = x[i];
    if (big == 0) return false;
    for (int i = 0; i <= 4; ++i)
        if (x[i] != 0 && std::fabs(big / x[i]) > kDifficultRatio) return true;
    return false;
}

// ---- Sturm bisection on [0, 1e7]

struct SturmPolynomial {
    int degree;
    Real c[kPovMaxOrder + 1];  // ascending powers

    Real operator()(Real x) const {
        Real v = c[degree];
        for (int i = degree - 1; i >= 0; --i) v = v * x + c[i];
        return v;
    }
};

// The remainder of u divided by v, whose leading coefficient is +1 or -1; remainder
// coefficients below 1e-10 are cleared from the top. Returns the remainder's degree.
int remainder(const SturmPolynomial& u, const SturmPolynomial& v, SturmPolynomial& r) {
    r.degree =
        u.degree;  // only the used coefficients: a whole SturmPolynomial is 37 doubles
    std::copy(u.c, u.c + u.degree + 1, r.c);
    const int top = v.degree;
    if (v.c[top] < 0) {
        // Dividing by -1 leading: alternate quotient signs folded into the update.
        for (int k = u.degree - top - 1; k >= 0; k -= 2) r.c[k] = -r.c[k];
        for (int k = u.degree - top; k >= 0; --k)
            for (int j = top + k - 1; j >= k; --j)
                r.c[j] = -r.c[j] - r.c[top + k] * v.c[j - k];
    } else {
        for (int k = u.degree - top; k >= 0; --k)
            for (int j = top + k - 1; j >= k; --j) r.c[j] -= r.c[top + k] * v.c[j - k];
    }
    int k = top - 1;
    while (k >= 0 && std::fabs(r.c[k]) < kSmallEnough) r.c[k--] = 0;
    r.degree = k < 0 ? 0 : k;
    return r.degree;
}

// frexp's exponent of a positive finite x (x < 2^e), read from its bits where x is
// normal: the call to frexp showed in the lathe field's profile (about 20 per sextic).
int binary_exponent(Real x) {
    const int biased = int(std::bit_cast<uint64_t>(x) >> 52) & 0x7ff;
    if (biased == 0) {
        int e;
        std::frexp(x, &e);
        return e;
    }
    return biased - 1022;
}

struct SturmChain {
    SturmPolynomial s[kPovMaxOrder + 2];
    int last;  // index of the final (constant) element

    // s[0] is the monic polynomial; then its derivative scaled to a unit leading
    // coefficient, then negated remainders scaled to leading -1, down to a constant,
    // which is negated unscaled.
    explicit SturmChain(const SturmPolynomial& p) {
        s[0].degree = p.degree;
        std::copy(p.c, p.c + p.degree + 1, s[0].c);
        const int n = p.degree;
        s[1].degree = n - 1;
        const Real f = std::fabs(p.c[n] * n);
        for (int i = 1; i <= n; ++i) s[1].c[i - 1] = p.c[i] * i / f;
        int k = 2;
        while (remainder(s[k - 2], s[k - 1], s[k]) != 0) {
            const Real g = -std::fabs(s[k].c[s[k].degree]);
            for (int i = s[k].degree; i >= 0; --i) s[k].c[i] /= g;
            ++k;
        }
        s[k].c[0] = -s[k].c[0];
        last = k;
        pack();
    }

    // A short chain (a sextic's has at most 7 elements) is also kept by power, each
    // element padded with leading zeros, so that changes() runs one Horner pass over all
    // elements at once (vectorised). The bits are each element's own Horner's rule: a
    // padding zero times x is zero, and zero plus the leading coefficient is that
    // coefficient; the steps after it are the element's.
    static constexpr int kLanes = 8;
    bool packed = false;
    int top = 0;                           // the highest degree in the chain
    alignas(64) Real by_power[8][kLanes];  // [power][element]
    void pack() {
        if (last >= kLanes || s[0].degree >= 8) return;
        top = s[0].degree;
        for (int j = 0; j <= top; ++j)
            for (int i = 0; i < kLanes; ++i)
                by_power[j][i] = i <= last && j <= s[i].degree ? s[i].c[j] : 0.0;
        packed = true;
    }

    // Above this x every element, evaluated by Horner's rule in doubles, has the sign of
    // its leading coefficient, so changes(x) is changes_at(true) without evaluating. The
    // computed value is the exact value of the element with each coefficient off by at
    // most gamma = 2 m u (m its degree, u the unit roundoff); Fujiwara's bound of that
    // perturbed polynomial (every complex root within 2 max |c_(m-i) / c_m|^(1/i)) is
    // taken with gamma (and the ratio's own rounding), each i-th root rounded up to a
    // power of two (the exponent, not pow: this runs once per polynomial).
    Real sign_settled_above() const {
        int bound_exponent = 0;  // the bound is 2^bound_exponent, at least 1
        for (int k = 0; k <= last; ++k) {
            const SturmPolynomial& e = s[k];
            const int m = e.degree;
            if (m == 0) continue;
            const Real gamma = (4.0 * m + 4) * 0x1p-53;
            const Real lead = std::fabs(e.c[m]) * (1 - gamma);
            if (!(lead > 0)) return kBracketEnd * 2;  // never settled: always evaluate
            for (int i = 1; i <= m; ++i) {
                const Real ratio = std::fabs(e.c[m - i]) * (1 + gamma) / lead;
                if (ratio == 0) continue;
                if (!std::isfinite(ratio)) return kBracketEnd * 2;
                // ratio < 2^exponent, so ratio^(1/i) < 2^ceil(exponent/i)
                const int exponent = binary_exponent(ratio);
                const int root_exponent =
                    exponent > 0 ? (exponent + i - 1) / i : -((-exponent) / i);
                bound_exponent = std::max(bound_exponent, 1 + root_exponent);
            }
        }
        return std::ldexp(1.0, bound_exponent);
    }

    // Sign changes along the chain at x; a zero value counts as a change after it.
    int changes(Real x) const {
        if (packed) {
            Real v[kLanes];
            for (int i = 0; i < kLanes; ++i) v[i] = by_power[top][i];
            for (int j = top - 1; j >= 0; --j)
                for (int i = 0; i < kLanes; ++i) v[i] = v[i] * x + by_power[j][i];
            int n = 0;
            for (int i = 1; i <= last; ++i)
                if (v[i - 1] == 0 || v[i - 1] * v[i] < 0) ++n;
            return n;
        }
        int n = 0;
        Real prev = s[0](x);
        for (int i = 1; i <= last; ++i) {
            const Real v = s[i](x);
            if (prev == 0 || prev * v < 0) ++n;
            prev = v;
        }
        return n;
    }
    // The same with each element's leading (x -> +inf) or constant (x = 0) coefficient.
    int changes_at(bool infinity) const {
        int n = 0;
        Real prev = infinity ? s[0].c[s[0].degree] : s[0].c[0];
        for (int i = 1; i <= last; ++i) {
            const Real v = infinity ? s[i].c[s[i].degree] : s[i].c[0];
            if (prev == 0 || prev * v < 0) ++n;
            prev = v;
        }
        return n;
    }
};

bool converged(Real lo, Real hi, Real x) {
    return std::fabs(x) > kRelError ? std::fabs((hi - lo) / x) < kRelError
                                    : std::fabs(hi - lo) < kRelError;
}

// Whether regula falsi from a = 0 (p(0) = fa) to b (p(b) = fb, of the other sign, both
// at least 1e-10 in magnitude) surely runs all its iterations without converging: it
// then returns false, and nothing it computed on the way is used. Each step moves a by
// at most |fa| b / |fb| (both terms of its quotient have one sign: a few ulps of
// rounding), and while p keeps fa's sign the same end moves and |fb| halves each step;
// so a stays below X = 2 (|fa| + S) b 2^50 / |fb| (S the sum of the other coefficients'
// magnitudes: |p(x) - p(0)| <= S x for x <= 1). Where X is below 1e-12 and |p| there
// stays above 1e-12, Horner's rounding included, no step converges and p keeps its
// sign. A lathe's sextic, steep at 1e7, searched from [0, 1e7] fails so in a quarter of
// its solves, at the cost of 50 evaluations each.
bool fails_from_zero(const SturmPolynomial& p, Real b, Real fa, Real fb) {
    const Real A = std::fabs(fa);
    Real S = 0;
    for (int i = 1; i <= p.degree; ++i) S += std::fabs(p.c[i]);
    const Real X = 2.0 * (A + S) * b * 0x1p50 / std::fabs(fb);
    if (!(std::isfinite(X) && b > 2 * kRelError && X <= kRelError)) return false;
    // Horner's error on [0, X] is below gamma(2 degree) (A + S x) < 1e-14 (A + S).
    return A - S * X - 1e-14 * (A + S) > 2 * kRelError;
}

// Illinois regula falsi on [a, b] for a single root of p.
bool regula_falsi(const SturmPolynomial& p, Real a, Real b, Real& root) {
    Real fa = p(a), fb = p(b);
    if (fa * fb > 0) return false;
    if (std::fabs(fa) < kSmallEnough) {
        root = a;
        return true;
    }
    if (std::fabs(fb) < kSmallEnough) {
        root = b;
        return true;
    }
    if (a == 0 && fails_from_zero(p, b, fa, fb)) return false;
    Real last_fx = fa;
    for (int i = 0; i < kMaxIterations; ++i) {
        const Real x = (fb * a - fa * b) / (fb - fa);
        const Real fx = p(x);
        if (std::fabs(x) > kRelError ? std::fabs(fx / x) < kRelError
                                     : std::fabs(fx) < kRelError) {
            root = x;
            return true;
        }
        // Replace the end whose value has fx's sign; when the same end is replaced
        // twice running, halve the kept end's value.
        const bool replace_a = fa < 0 ? fx < 0 : !(fx < 0);
        const bool same_side = last_fx * fx > 0;
        if (replace_a) {
            a = x;
            fa = fx;
            if (same_side) fb /= 2;
        } else {
            b = x;
            fb = fx;
            if (same_side) fa /= 2;
        }
        if (std::fabs(b - a) < kRelError) {
            root = x;
            return true;
        }
        last_fx = fx;
    }
    return false;
}

// The part of POV-Ray's bisection that finds roots up to `wanted`, with the same results
// there: an interval starting above `wanted` (roots the caller drops) is not searched,
// and above `settled` the sign changes are known without evaluating the chain. The path
// of the search (which intervals recurse, the regula falsi tried on entry, the iteration
// count) stays POV-Ray's, so the roots it keeps are bit for bit its roots.
struct Bisection {
    const SturmChain& chain;
    Real wanted;   // largest root the caller keeps, with a margin for rounding
    Real settled;  // sign_settled_above()
    int at_infinity;

    int changes(Real x) const { return x > settled ? at_infinity : chain.changes(x); }

    int run(Real lo, Real hi, int at_lo, int at_hi, Real* roots) const {
        if (lo > wanted) return 0;
        if (at_lo - at_hi == 1 && regula_falsi(chain.s[0], lo, hi, roots[0])) return 1;
        const bool single = at_lo - at_hi == 1;
        Real mid = lo;
        for (int i = 0; i < kMaxIterations; ++i) {
            mid = (lo + hi) / 2;
            const int at_mid = changes(mid);
            if (at_mid < at_hi || at_mid > at_lo)
                return 0;  // inconsistent counts: give up
            if (converged(lo, hi, mid)) {
                roots[0] = mid;
                return 1;
            }
            const int left = at_lo - at_mid, right = at_mid - at_hi;
            if (!single && left != 0 && right != 0) {
                const int n = run(lo, mid, at_lo, at_mid, roots);
                return n + run(mid, hi, at_mid, at_hi, roots + n);
            }
            if (left == 0) {
                if (mid > wanted) return 0;
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
};

int sturm_roots(int n, const Real* c, Real* roots, Real wanted) {
    SturmPolynomial p;
    p.degree = n;
    for (int i = 0; i <= n; ++i) p.c[n - i] = c[i] / c[0];
    const SturmChain chain(p);
    const int at_infinity = chain.changes_at(true);
    if (chain.changes_at(false) == at_infinity) return 0;
    // A root returned from [lo, hi] lies there up to regula falsi's rounding; the margin
    // keeps every root at or below `wanted` that POV-Ray's whole search would return.
    const Bisection search{
        chain, wanted < kBracketEnd ? wanted * (1 + 1e-6) + 1e-300 : kBracketEnd,
        chain.sign_settled_above(), at_infinity};
    const int at_lo = chain.changes(0), at_hi = search.changes(kBracketEnd);
    if (at_lo == at_hi) return 0;
    return search.run(0, kBracketEnd, at_lo, at_hi, roots);
}

}  // namespace

int pov_solve_polynomial(int n, const Real* c, Real* roots, bool sturm,
                         Real root_elimination, Real wanted) {
    int skip = 0;
    while (skip < n && std::fabs(c[skip]) < kSmallEnough) ++skip;
    n -= skip;
    c += skip;
    const bool eliminate = n >= 3 && root_elimination > 0 && c[n - 1] != 0 &&
                           std::fabs(c[n] / c[n - 1]) < root_elimination;
    switch (n) {
        case 0:
            return 0;
        case 1:
            if (c[0] == 0) return 0;
            roots[0] = -c[1] / c[0];
            return 1;
        case 2:
            return quadratic(c, roots);
        case 3:
            if (eliminate) return quadratic(c, roots);
            return sturm ? sturm_roots(3, c, roots, wanted) : cubic(c, roots);
        case 4:
            if (eliminate)
                return sturm ? sturm_roots(3, c, roots, wanted) : cubic(c, roots);
            if (sturm || difficult(c)) return sturm_roots(4, c, roots, wanted);
            return quartic(c, roots);
        default:
            // POV-Ray also solves the eliminated polynomial here, then overwrites the
            // result.
            return sturm_roots(n, c, roots, wanted);
    }
}

}  // namespace povwall
