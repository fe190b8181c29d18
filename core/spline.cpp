// Spline evaluation after POV-Ray 3.7's behaviour (described in its manual and measured
// against povray 3.7.0.10; see core/spline.h). The orders of operations are deliberate:
// they give POV-Ray's bits.
#include "core/spline.h"

#include <algorithm>

namespace povwall {

namespace {

using Values = std::array<double, 5>;

// POV-Ray's segment search: 0 at or below the first t, n at or above the last, otherwise
// the first point with t >= p (an interior knot ends the segment before it).
size_t find_segment(const std::vector<Spline::Point>& pts, double p) {
    const size_t n = pts.size();
    if (n == 0 || p <= pts[0].t) return 0;
    if (p >= pts[n - 1].t) return n;
    return size_t(
        std::lower_bound(pts.begin(), pts.end(), p,
                         [](const Spline::Point& a, double x) { return a.t < x; }) -
        pts.begin());
}

// Second derivatives of the natural cubic through the points (zero at both ends).
void solve_natural(const std::vector<Spline::Point>& pts, std::vector<Values>& m) {
    const size_t n = pts.size();
    m.assign(n, Values{});
    if (n < 3) return;
    std::vector<double> h(n - 1), b(n - 1), u(n - 1), w(n - 1);
    for (int k = 0; k < 5; ++k) {
        for (size_t j = 0; j + 1 < n; ++j) {
            h[j] = pts[j + 1].t - pts[j].t;
            b[j] = (pts[j + 1].v[size_t(k)] - pts[j].v[size_t(k)]) / h[j];
        }
        u[1] = 2 * (h[0] + h[1]);
        w[1] = 6 * (b[1] - b[0]);
        for (size_t j = 2; j + 1 < n; ++j) {
            u[j] = 2 * (h[j] + h[j - 1]) - (h[j - 1] * h[j - 1]) / u[j - 1];
            w[j] = 6 * (b[j] - b[j - 1]) - (h[j - 1] * w[j - 1]) / u[j - 1];
        }
        m[n - 1][size_t(k)] = 0;
        for (size_t j = n - 2; j >= 1; --j)
            m[j][size_t(k)] = (w[j] - h[j] * m[j + 1][size_t(k)]) / u[j];
        m[0][size_t(k)] = 0;
    }
}

double linear(const Spline::Point& a, const Spline::Point& b, int k, double p) {
    const double va = a.v[size_t(k)], vb = b.v[size_t(k)];
    return ((p - a.t) * (vb - va)) / (b.t - a.t) + va;
}

// The parabola through three points, as POV-Ray writes its coefficients.
double quadratic(const Spline::Point& a, const Spline::Point& b, const Spline::Point& c,
                 int k, double p) {
    const double p1 = a.t, p2 = b.t, p3 = c.t;
    const double v1 = a.v[size_t(k)], v2 = b.v[size_t(k)], v3 = c.v[size_t(k)];
    const double n = ((p2 - p1) * (p3 - p1)) * (p3 - p2);
    const double qa =
        ((((((-p2) * v1 + p3 * v1) + p1 * v2) - p3 * v2) - p1 * v3) + p2 * v3) / n;
    const double qb = (((((p2 * p2 * v1 - p3 * p3 * v1) - p1 * p1 * v2) + p3 * p3 * v2) +
                        p1 * p1 * v3) -
                       p2 * p2 * v3) /
                      n;
    const double qc =
        ((((((-p2) * p2 * p3 * v1 + p2 * p3 * p3 * v1) + p1 * p1 * p3 * v2) -
           p1 * p3 * p3 * v2) -
          p1 * p1 * p2 * v3) +
         p1 * p2 * p2 * v3) /
        n;
    return (qa * p + qb) * p + qc;
}

double slope(const std::vector<Spline::Point>& pts, size_t a, size_t b, int k) {
    return (pts[b].v[size_t(k)] - pts[a].v[size_t(k)]) / (pts[b].t - pts[a].t);
}

}  // namespace

void spline_insert(Spline& s, double t, const Values& v) {
    auto& pts = s.points;
    const size_t n = pts.size();
    const size_t i = find_segment(pts, t);
    if (n > 0 && i < n && pts[i].t == t) {
        pts[i].v = v;
    } else if (n > 0 && i == n && pts[n - 1].t == t) {
        // POV-Ray 3.7 writes it past the end and drops it (3.8 replaces the point).
        return;
    } else {
        pts.insert(pts.begin() + std::ptrdiff_t(i), Spline::Point{t, v});
    }
    solve_natural(pts, s.second_derivatives);
}

Values spline_evaluate(const Spline& s, double p, Spline::Kind kind) {
    const auto& pts = s.points;
    const size_t last = pts.size() - 1;
    if (last == 0) return pts[0].v;
    const size_t i = find_segment(pts, p);
    Values r{};
    switch (kind) {
        case Spline::Kind::Linear:
            if (i == 0) return pts[0].v;
            if (i > last) return pts[last].v;
            for (int k = 0; k < 5; ++k) r[size_t(k)] = linear(pts[i - 1], pts[i], k, p);
            return r;
        case Spline::Kind::Quadratic: {
            if (i == 0) return pts[0].v;
            if (i > last) return pts[last].v;
            if (last == 1) {
                for (int k = 0; k < 5; ++k) r[size_t(k)] = linear(pts[0], pts[1], k, p);
                return r;
            }
            const size_t c = i > 1 ? i - 1 : 1;
            for (int k = 0; k < 5; ++k)
                r[size_t(k)] = quadratic(pts[c - 1], pts[c], pts[c + 1], k, p);
            return r;
        }
        case Spline::Kind::Natural: {
            if (i == 0) return pts[0].v;
            if (i > last) return pts[last].v;
            const size_t j = i - 1;
            const double h = pts[j + 1].t - pts[j].t, d = p - pts[j].t;
            for (int k = 0; k < 5; ++k) {
                const size_t kk = size_t(k);
                const double m0 = s.second_derivatives[j][kk];
                const double m1 = s.second_derivatives[j + 1][kk];
                const double v0 = pts[j].v[kk], v1 = pts[j + 1].v[kk];
                double q = m0 / 2.0 + (d * (m1 - m0)) / (6.0 * h);
                q = ((-(h / 6.0)) * (m1 + 2.0 * m0) + (v1 - v0) / h) + d * q;
                r[kk] = v0 + d * q;
            }
            return r;
        }
        case Spline::Kind::Cubic: {
            if (last == 1) {
                for (int k = 0; k < 5; ++k)
                    r[size_t(k)] = (pts[0].v[size_t(k)] + pts[1].v[size_t(k)]) / 2.0;
                return r;
            }
            if (i < 2) return pts[1].v;
            if (i >= last) return pts[last - 1].v;
            const size_t j = i - 1;
            const double dt = pts[j + 1].t - pts[j].t;
            const double u = (p - pts[j].t) / dt;
            for (int k = 0; k < 5; ++k) {
                const size_t kk = size_t(k);
                const double s01 = slope(pts, j - 1, j, k), s12 = slope(pts, j, j + 1, k);
                const double s23 = slope(pts, j + 1, j + 2, k);
                const double d0 = ((s01 + s12) / 2.0) * dt;
                const double d1 = ((s23 + s12) / 2.0) * dt;
                r[kk] = ((pts[j].v[kk] * ((((2 * u) * u) * u - (3 * u) * u) + 1) +
                          pts[j + 1].v[kk] * ((3 * u) * u - ((2 * u) * u) * u)) +
                         d0 * ((((u * u) * u) - (2 * u) * u) + u)) +
                        d1 * ((u * u) * u - u * u);
            }
            return r;
        }
    }
    return r;
}

}  // namespace povwall
