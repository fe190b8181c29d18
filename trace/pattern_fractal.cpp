// The fractal patterns mandel, julia and magnet in the x-y plane, as POV-Ray 3.7 defines
// them (pattern.cpp of 3.7-stable read for semantics): the iterated formula, the escape
// test, and the exterior/interior colourings of the escaping and the staying points.
#include <array>
#include <cmath>

#include "trace/pattern_internal.h"

namespace povwall::trace::detail {
namespace {

// The value of a point that escaped at iteration `col` with z = (a, b) (POV-Ray's
// fractal_exterior_color).
Real exterior_value(const PatternSpec::Fractal& f, int col, int iterations, Real a,
                    Real b) {
    const Real e = f.exterior_factor;
    switch (f.exterior_type) {
        case 0:
            return e;
        case 1:
            return Real(col) / Real(iterations);
        case 2:
            return a * e;
        case 3:
            return b * e;
        case 4:
            return a * a * e;
        case 5:
            return b * b * e;
        case 6:
            return std::sqrt(a * a + b * b) * e;
        case 7: {  // 0 .. (n-1)/n
            const auto n = unsigned(e);
            return n ? Real(unsigned(col) % n) / e : 0.0;
        }
        case 8: {  // 0 .. 1
            const auto n = unsigned(1 + e);
            return n ? Real(unsigned(col) % n) / e : 0.0;
        }
        default:
            return 0;
    }
}

// The value of a point that stayed, ending at z = (a, b) with `mindist2` the smallest
// |z|^2 seen (POV-Ray's fractal_interior_color, type 6's missing parentheses included).
Real interior_value(const PatternSpec::Fractal& f, Real a, Real b, Real mindist2) {
    const Real i = f.interior_factor;
    switch (f.interior_type) {
        case 0:
            return i;
        case 1:
            return std::sqrt(mindist2) * i;
        case 2:
            return a * i;
        case 3:
            return b * i;
        case 4:
            return a * a * i;
        case 5:
            return b * b * i;
        case 6:
            return a * a + b * b * i;  // sic
        default:
            return 0;
    }
}

// Iterates z = (a, b) with `step` (which writes the next a and b) until `escaped(a, b,
// |z|^2)` or the iteration count; `mindist2` starts as given.
template <typename Step, typename Escaped>
Real iterate(const PatternSpec::Fractal& f, int iterations, Real a, Real b, Real mindist2,
             Step step, Escaped escaped) {
    for (int col = 0; col < iterations; ++col) {
        step(a, b);
        const Real dist2 = a * a + b * b;
        if (dist2 < mindist2) mindist2 = dist2;
        if (escaped(a, b, dist2)) return exterior_value(f, col, iterations, a, b);
    }
    return interior_value(f, a, b, mindist2);
}

// (a + bi)^n's coefficients: C(n, k) times the sign of i^k's real or imaginary part
// (negative when bit 1 of k is set), for n up to 33 (POV-Ray's limit).
struct PowerCoefficients {
    std::array<std::array<double, 34>, 34> c{};
    PowerCoefficients() {
        for (int n = 0; n <= 33; ++n) {
            c[n][0] = 1;
            for (int k = 1; k <= n; ++k)
                c[n][k] = k == n ? 1 : c[n - 1][k - 1] + c[n - 1][k];
        }
        for (int n = 0; n <= 33; ++n)
            for (int k = 1; k <= n; ++k)
                if (k & 2) c[n][k] = -c[n][k];
    }
};
const PowerCoefficients kPower;

// z^n + c for the exponents 2, 3, 4 (written out) and 5..33 (binomial sums).
struct PowerStep {
    int n;
    Real cr, ci;
    void operator()(Real& a, Real& b) const {
        const Real a2 = a * a, b2 = b * b;
        switch (n) {
            case 2: {
                const Real nb = 2.0 * a * b + ci;
                a = a2 - b2 + cr;
                b = nb;
                return;
            }
            case 3: {
                const Real nb = 3.0 * a2 * b - b2 * b + ci;
                a = a2 * a - 3.0 * a * b2 + cr;
                b = nb;
                return;
            }
            case 4: {
                const Real nb = 4.0 * (a2 * a * b - a * b2 * b) + ci;
                a = a2 * a2 - 6.0 * a2 * b2 + b2 * b2 + cr;
                b = nb;
                return;
            }
            default: {
                const auto& c = kPower.c[size_t(n)];
                Real na = std::pow(a, n);
                for (int k = 2; k <= n; k += 2)
                    na += c[size_t(k)] * std::pow(a, n - k) * std::pow(b, k);
                Real nb = 0;
                for (int k = 1; k <= n; k += 2)
                    nb += c[size_t(k)] * std::pow(a, n - k) * std::pow(b, k);
                a = na + cr;
                b = nb + ci;
                return;
            }
        }
    }
};

// Magnet formula 1, z -> ((z^2 + c - 1) / (2z + c - 2))^2, and formula 2,
// z -> ((z^3 + 3(c-1)z + (c-1)(c-2)) / (3z^2 + 3(c-2)z + (c-1)(c-2) + 1))^2.
struct MagnetStep {
    int formula;
    Real cr, ci;
    void operator()(Real& a, Real& b) const {
        const Real a2 = a * a, b2 = b * b;
        Real nr, ni, dr, di;  // numerator, denominator
        if (formula == 1) {
            nr = a2 - b2 + cr - 1;
            ni = 2 * a * b + ci;
            dr = 2 * a + cr - 2;
            di = 2 * b + ci;
        } else {
            const Real c1r = cr - 1, c2r = cr - 2;
            const Real c1c2r = c1r * c2r - ci * ci, c1c2i = (c1r + c2r) * ci;
            nr = a2 * a - 3 * a * b2 + 3 * (a * c1r - b * ci) + c1c2r;
            ni = 3 * a2 * b - b2 * b + 3 * (a * ci + b * c1r) + c1c2i;
            dr = 3 * (a2 - b2) + 3 * (a * c2r - b * ci) + c1c2r + 1;
            di = 6 * a * b + 3 * (a * ci + b * c2r) + c1c2i;
        }
        const Real d = dr * dr + di * di;
        const Real qa = (nr * dr + ni * di) / d, qb = (ni * dr - nr * di) / d;
        const Real qb2 = qb * qb;
        b = 2 * qa * qb;
        a = qa * qa - qb2;
    }
};

}  // namespace

Real fractal_value(const PatternSpec& s, const Point3& p) {
    const PatternSpec::Fractal& f = s.fractal;
    const int iterations = int(s.scalar);
    const Real x = p.x, y = p.y;
    auto outside_radius_2 = [](Real, Real, Real dist2) { return dist2 > 4.0; };
    switch (s.kind) {
        case PatternKind::Mandel:
            return iterate(f, iterations, x, y, x * x + y * y,
                           PowerStep{f.exponent, x, y}, outside_radius_2);
        case PatternKind::Julia:
            return iterate(f, iterations, x, y, x * x + y * y,
                           PowerStep{f.exponent, f.c_re, f.c_im}, outside_radius_2);
        case PatternKind::Magnet: {
            // Escapes far out or onto the fixed point 1.
            auto escaped = [](Real a, Real b, Real dist2) {
                const Real d = a - 1;
                return dist2 > 10000.0 || d * d + b * b < 1 / 10000.0;
            };
            if (f.magnet_julia)
                return iterate(f, iterations, x, y, x * x + y * y,
                               MagnetStep{f.magnet_formula, f.c_re, f.c_im}, escaped);
            return iterate(f, iterations, 0.0, 0.0, 10000.0,
                           MagnetStep{f.magnet_formula, x, y}, escaped);
        }
        default:
            return 0;
    }
}

}  // namespace povwall::trace::detail
