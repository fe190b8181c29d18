// prism { [spline] [sweep] H1, H2, N, <u, v>... [open] }: the points become the cubic
// segments POV-Ray 3.7's Parse_Prism and Compute_Prism make of them, with their closure
// rules, warnings and errors.
#include <algorithm>
#include <array>
#include <cmath>

#include "parser/interpreter.h"

namespace povwall::parser {
namespace {

using UV = std::array<Real, 2>;

constexpr Real kEpsilon = 1e-10;

bool same_point(const UV& a, const UV& b) {
    return std::fabs(a[0] - b[0]) < kEpsilon && std::fabs(a[1] - b[1]) < kEpsilon;
}

// x^2-free roots of 3a t^2 + 2b t + c in POV-Ray's solver order (a segment's extrema).
int extrema(Real a, Real b, Real c, Real roots[2]) {
    Real k[3] = {3 * a, 2 * b, c};
    int i = 0;
    while (i < 2 && std::fabs(k[i]) < kEpsilon) ++i;
    if (i == 2) return 0;
    if (i == 1) {
        roots[0] = -k[2] / k[1];
        return 1;
    }
    const Real B = -k[1] / k[0], C = k[2] / k[0], d = B * B - 4 * C;
    if (d > -kEpsilon && d < kEpsilon) {
        roots[0] = B / 2;
        return 1;
    }
    if (d < 0) return 0;
    roots[0] = (B + std::sqrt(d)) / 2;
    roots[1] = (B - std::sqrt(d)) / 2;
    return 2;
}

PrismSegment make_segment(Prism::Spline spline, const UV* p) {
    PrismSegment s{};
    for (int a = 0; a < 2; ++a) {
        switch (spline) {
            case Prism::Spline::Linear:
                s.a[a] = s.b[a] = 0;
                s.c[a] = p[1][a] - p[0][a];
                s.d[a] = p[0][a];
                break;
            case Prism::Spline::Quadratic:
                s.a[a] = 0;
                s.b[a] = 0.5 * p[0][a] - p[1][a] + 0.5 * p[2][a];
                s.c[a] = 0.5 * (p[2][a] - p[0][a]);
                s.d[a] = p[1][a];
                break;
            case Prism::Spline::Cubic:  // Catmull-Rom through p1 -> p2
                s.a[a] = -0.5 * p[0][a] + 1.5 * p[1][a] - 1.5 * p[2][a] + 0.5 * p[3][a];
                s.b[a] = p[0][a] - 2.5 * p[1][a] + 2 * p[2][a] - 0.5 * p[3][a];
                s.c[a] = -0.5 * p[0][a] + 0.5 * p[2][a];
                s.d[a] = p[1][a];
                break;
            case Prism::Spline::Bezier:  // runs from p3 (t = 0) to p0
                s.a[a] = p[0][a] - 3 * p[1][a] + 3 * p[2][a] - p[3][a];
                s.b[a] = 3 * p[1][a] - 6 * p[2][a] + 3 * p[3][a];
                s.c[a] = 3 * p[2][a] - 3 * p[3][a];
                s.d[a] = p[3][a];
                break;
        }
    }
    // The rectangle: the end points (all four control points of a Bezier), and for
    // quadratic and cubic segments the curve at its extrema, which take the places of
    // the first values in the order the solver gives them.
    Real v[2][4];
    for (int a = 0; a < 2; ++a) {
        const bool ends =
            spline == Prism::Spline::Quadratic || spline == Prism::Spline::Cubic;
        if (spline == Prism::Spline::Bezier) {
            for (int k = 0; k < 4; ++k) v[a][k] = p[k][a];
        } else {
            const UV& e0 = ends ? p[1] : p[0];
            const UV& e1 = ends ? p[2] : p[1];
            v[a][0] = v[a][2] = e0[a];
            v[a][1] = v[a][3] = e1[a];
        }
        if (ends) {
            Real t[2];
            const int n = extrema(s.a[a], s.b[a], s.c[a], t);
            for (int k = 0; k < n; ++k) {
                if (t[k] >= 0 && t[k] <= 1)
                    v[a][k] = t[k] * (t[k] * (t[k] * s.a[a] + s.b[a]) + s.c[a]) + s.d[a];
            }
        }
    }
    s.x1 = std::min(std::min(v[0][0], v[0][1]), std::min(v[0][2], v[0][3]));
    s.x2 = std::max(std::max(v[0][0], v[0][1]), std::max(v[0][2], v[0][3]));
    s.y1 = std::min(std::min(v[1][0], v[1][1]), std::min(v[1][2], v[1][3]));
    s.y2 = std::max(std::max(v[1][0], v[1][1]), std::max(v[1][2], v[1][3]));
    s.u2 = s.x2;
    s.v1 = s.y1;
    s.v2 = s.y2;
    return s;
}

// The range of x * h for x in [lo, hi] and h in [h1, h2] (a conic prism's rectangle).
void scale_range(Real& lo, Real& hi, Real h1, Real h2) {
    const Real c[4] = {lo * h1, lo * h2, hi * h1, hi * h2};
    lo = std::min({c[0], c[1], c[2], c[3]});
    hi = std::max({c[0], c[1], c[2], c[3]});
}

}  // namespace

void Interpreter::parse_prism(Object& out, const Token& keyword) {
    Prism prism;
    for (;;) {
        const Token& t = peek();
        if (is_word(t, "linear_spline"))
            prism.spline = Prism::Spline::Linear;
        else if (is_word(t, "quadratic_spline"))
            prism.spline = Prism::Spline::Quadratic;
        else if (is_word(t, "cubic_spline"))
            prism.spline = Prism::Spline::Cubic;
        else if (is_word(t, "bezier_spline"))
            prism.spline = Prism::Spline::Bezier;
        else if (is_word(t, "linear_sweep"))
            prism.conic = false;
        else if (is_word(t, "conic_sweep"))
            prism.conic = true;
        else
            break;
        next();
    }
    Real h1 = parse_float();
    accept_punct(',');
    Real h2 = parse_float();
    accept_punct(',');
    if (h1 > h2) std::swap(h1, h2);
    prism.height1 = h1;
    prism.height2 = h2;
    const Token count_at = peek();
    const int n = int(parse_float());
    using S = Prism::Spline;
    switch (prism.spline) {
        case S::Linear:
            if (n < 3)
                error(count_at,
                      "Prism with linear splines must have at least three points.");
            break;
        case S::Quadratic:
            if (n < 5)
                error(count_at,
                      "Prism with quadratic splines must have at least five points.");
            break;
        case S::Cubic:
            if (n < 6)
                error(count_at,
                      "Prism with cubic splines must have at least six points.");
            break;
        case S::Bezier:
            if (n % 4 != 0)
                error(count_at,
                      "Prism with Bezier splines must have four points per segment.");
            break;
    }
    std::vector<UV> pts;
    pts.reserve(size_t(std::clamp(n, 0, 1 << 16)));  // a claimed count is not trusted
    for (int i = 0; i < n; ++i) {
        accept_punct(',');
        const Token at = peek();
        const Numeric v = parse_numeric();
        if (v.size > 2)
            error(at, "UV_Vector expected but vector or color expression found.");
        pts.push_back({v.c[0], v.size == 1 ? v.c[0] : v.c[1]});
    }
    if (accept_word("open")) prism.open = true;

    // Whether the last sub-curve closes (POV-Ray's check: a point equal to the
    // sub-curve's first point closes it, and the next sub-curve starts after it).
    bool closed = false;
    UV start = prism.spline == S::Linear ? pts[0] : pts[1];
    if (prism.spline == S::Bezier) {
        closed = true;
        size_t loop = 0;
        for (size_t i = 4; i < pts.size(); i += 4) {
            if (!same_point(pts[i], pts[i - 1])) {
                if (!same_point(pts[i - 1], pts[loop])) {
                    closed = false;
                    break;
                }
                loop = i;
            }
        }
        if (!same_point(pts.back(), pts[loop])) closed = false;
    } else {
        const size_t jump = prism.spline == S::Linear      ? 1
                            : prism.spline == S::Quadratic ? 2
                                                           : 3;
        for (size_t i = prism.spline == S::Linear ? 1 : 2; i < pts.size(); ++i) {
            closed = false;
            if (same_point(pts[i], start)) {
                closed = true;
                i += jump;
                if (i < pts.size()) start = pts[i];
            }
        }
    }
    if (!closed) {
        if (prism.spline == S::Linear) {
            warn(keyword, "Linear prism not closed. Closing it.");
            pts.push_back(start);
        } else {
            warn(keyword, "Prism not closed. Ignoring it.");
            prism.degenerate = true;
        }
    }

    // The segments, sub-curve after sub-curve.
    const size_t count = pts.size();
    UV first = prism.spline == S::Linear ? pts[0] : pts[1];
    for (size_t i = 0; i + 1 < count; ++i) {
        const size_t need = prism.spline == S::Linear      ? 2
                            : prism.spline == S::Quadratic ? 3
                                                           : 4;
        if (i + need > count) error(keyword, "Too few points in prism.");
        prism.segments.push_back(make_segment(prism.spline, &pts[i]));
        switch (prism.spline) {
            case S::Linear:
                if (same_point(pts[i + 1], first)) {
                    i += 1;
                    if (i + 1 < count) first = pts[i + 1];
                }
                break;
            case S::Quadratic:
                if (same_point(pts[i + 2], first)) {
                    i += 2;
                    if (i + 2 < count) first = pts[i + 2];
                }
                break;
            case S::Cubic:
                if (same_point(pts[i + 2], first)) {
                    i += 3;
                    if (i + 2 < count) first = pts[i + 2];
                }
                break;
            case S::Bezier:
                i += 3;
                break;
        }
    }
    bool any = false;
    for (const PrismSegment& s : prism.segments) {
        prism.x1 = any ? std::min(prism.x1, s.x1) : s.x1;
        prism.x2 = any ? std::max(prism.x2, s.x2) : s.x2;
        prism.y1 = any ? std::min(prism.y1, s.y1) : s.y1;
        prism.y2 = any ? std::max(prism.y2, s.y2) : s.y2;
        any = true;
    }
    prism.u1 = prism.x1;
    prism.u2 = prism.x2;
    prism.v1 = prism.y1;
    prism.v2 = prism.y2;
    if (prism.conic) {
        for (PrismSegment& s : prism.segments) {
            scale_range(s.x1, s.x2, h1, h2);
            scale_range(s.y1, s.y2, h1, h2);
        }
        scale_range(prism.x1, prism.x2, h1, h2);
        scale_range(prism.y1, prism.y2, h1, h2);
    }
    out.shape = std::move(prism);
}

}  // namespace povwall::parser
