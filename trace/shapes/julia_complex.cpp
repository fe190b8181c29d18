#include "trace/shapes/julia_complex.h"

#include <cmath>

namespace povwall::trace {
namespace {

using Function = JuliaFractal::Function;

Complex mul(const Complex& a, const Complex& b) {
    return {a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re};
}

// a / b through b's conjugate over |b|^2; false (nothing written) when b = 0.
bool div(const Complex& a, const Complex& b, Complex& out) {
    const Real mod = b.re * b.re + b.im * b.im;
    if (mod == 0) return false;
    const Real p = b.re / mod, q = -b.im / mod;
    out = {a.re * p - a.im * q, a.re * q + a.im * p};
    return true;
}

// ln|z| taken of the square root of |z|^2, as POV-Ray does (not half the log).
Complex ln(const Complex& z) {
    return {std::log(std::sqrt(z.re * z.re + z.im * z.im)), std::atan2(z.im, z.re)};
}

Complex principal_sqrt(const Complex& z) {
    if (z.re == 0 && z.im == 0) return {0, 0};
    const Real mag = std::sqrt(std::sqrt(z.re * z.re + z.im * z.im));
    const Real half_arg = std::atan2(z.im, z.re) / 2;
    return {mag * std::cos(half_arg), mag * std::sin(half_arg)};
}

// -i ln(w): the last step of asin and acos.
Complex times_minus_i(const Complex& l) { return {l.im, -l.re}; }

// atanh z = ln((1 + z) / (1 - z)) / 2, with POV-Ray's special cases on the axes.
void atanh_into(const Complex& z, Complex& out) {
    if (z.re == 0) {
        out = {0, std::atan(z.im)};
    } else if (std::fabs(z.re) == 1 && z.im == 0) {
        // the pole: POV-Ray leaves the result unassigned
    } else if (std::fabs(z.re) < 1 && z.im == 0) {
        out = {std::log((1 + z.re) / (1 - z.re)) / 2, 0};
    } else {
        Complex q;  // 1 - z = 0 only at the pole handled above
        div({1 + z.re, z.im}, {1 - z.re, -z.im}, q);
        const Complex l = ln(q);
        out = {0.5 * l.re, 0.5 * l.im};
    }
}

// atan z = (i/2) ln((1 - iz) / (1 + iz)), with POV-Ray's special cases on the axes.
Complex atan_of(const Complex& z) {
    if (z.re == 0 && z.im == 0) return {0, 0};
    if (z.im == 0) return {std::atan(z.re), 0};
    if (z.re == 0) {
        // i atanh(-i z) = i atanh(y): atanh's pole leaves (y, 0) in place
        Complex t{z.im, 0};
        atanh_into(t, t);
        return {-t.im, t.re};
    }
    const Complex iz{-z.im, z.re};
    Complex q;  // 1 + iz = 0 needs z = i, on the axis handled above
    div({1 - iz.re, -iz.im}, {1 + iz.re, iz.im}, q);
    const Complex l = ln(q);
    return {-l.im * 0.5, 0.5 * l.re};
}

}  // namespace

void complex_function(Function f, const Complex& exponent, const Complex& z,
                      Complex& out) {
    const Real x = z.re, y = z.im;
    switch (f) {
        case Function::Exp: {
            const Real e = std::exp(x);
            out = {e * std::cos(y), e * std::sin(y)};
            return;
        }
        case Function::Ln:
            out = ln(z);
            return;
        case Function::Sin:
            out = {std::sin(x) * std::cosh(y), std::cos(x) * std::sinh(y)};
            return;
        case Function::Asin: {
            Complex s = mul(z, z);
            s = principal_sqrt({1 - s.re, -s.im});
            out = times_minus_i(ln({s.re - y, s.im + x}));  // ln(iz + sqrt(1 - z^2))
            return;
        }
        case Function::Cos:
            out = {std::cos(x) * std::cosh(y), -std::sin(x) * std::sinh(y)};
            return;
        case Function::Acos: {
            Complex s = mul(z, z);
            s = principal_sqrt({s.re - 1, s.im});
            out = times_minus_i(ln({s.re + x, s.im + y}));  // ln(z + sqrt(z^2 - 1))
            return;
        }
        case Function::Tan: {
            const Real denom = std::cos(2 * x) + std::cosh(2 * y);
            if (denom != 0) out = {std::sin(2 * x) / denom, std::sinh(2 * y) / denom};
            return;
        }
        case Function::Atan:
            out = atan_of(z);
            return;
        case Function::Sinh:
            out = {std::sinh(x) * std::cos(y), std::cosh(x) * std::sin(y)};
            return;
        case Function::Asinh: {
            Complex s = mul(z, z);
            s = principal_sqrt({s.re + 1, s.im});
            out = ln({s.re + x, s.im + y});
            return;
        }
        case Function::Cosh:
            out = {std::cosh(x) * std::cos(y), std::sinh(x) * std::sin(y)};
            return;
        case Function::Acosh: {
            Complex s = mul(z, z);
            s = principal_sqrt({s.re - 1, s.im});
            out = ln({x + s.re, y + s.im});
            return;
        }
        case Function::Tanh: {
            const Real denom = std::cosh(2 * x) + std::cos(2 * y);
            if (denom != 0) out = {std::sinh(2 * x) / denom, std::sin(2 * y) / denom};
            return;
        }
        case Function::Atanh:
            atanh_into(z, out);
            return;
        case Function::Pwr: {
            if (x == 0 && y == 0) {
                out = {0, 0};
                return;
            }
            const Complex t = mul(ln(z), exponent);
            const Real e = t.re < -690 ? 0 : std::exp(t.re);  // POV-Ray's underflow cut
            out = {e * std::cos(t.im), e * std::sin(t.im)};
            return;
        }
        case Function::Sqr:
        case Function::Cube:
        case Function::Reciprocal:
            return;  // not complex functions: julia_fractal.cpp iterates these itself
    }
}

Quad hypercomplex_function(const JuliaFractal& j, const Quad& q) {
    const Real x = q[0], y = q[1], z = q[2], w = q[3];
    const Complex e{j.exponent[0], j.exponent[1]};
    // Unassigned results (see complex_function) come out as 0.
    Complex fa, fb;
    complex_function(j.function, e, {x - w, y + z}, fa);
    complex_function(j.function, e, {x + w, y - z}, fb);
    return {0.5 * (fa.re + fb.re), 0.5 * (fa.im + fb.im), 0.5 * (fa.im - fb.im),
            0.5 * (fb.re - fa.re)};
}

}  // namespace povwall::trace
