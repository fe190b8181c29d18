// The spline of a surface of revolution (scene.h), as POV-Ray's Compute_Sor builds it.
#include <algorithm>
#include <cmath>

#include "core/math_constants.h"
#include "core/pov_matrix_inverse.h"
#include "core/pov_polysolve.h"
#include "core/scene.h"

namespace povwall {

std::string make_sor_spline(const std::vector<ProfilePoint>& p, SorSpline& out) {
    const size_t n = p.size() - 3;
    out = SorSpline{};
    std::vector<Real> r1(n), r2(n), h1(n), h2(n);
    Real xmin = 2e10, xmax = -2e10, ymin = 2e10, ymax = -2e10;
    for (size_t i = 0; i < n; ++i) {
        if (std::fabs(p[i + 2].y - p[i].y) < kPovEpsilon ||
            std::fabs(p[i + 3].y - p[i + 1].y) < kPovEpsilon)
            return "Incorrect point in surface of revolution";
        // r^2 at the segment's ends, and its slopes from the central differences of r.
        Real k[4] = {p[i + 1].x * p[i + 1].x, p[i + 2].x * p[i + 2].x,
                     (p[i + 2].x - p[i].x) / (p[i + 2].y - p[i].y),
                     (p[i + 3].x - p[i + 1].x) / (p[i + 3].y - p[i + 1].y)};
        k[2] *= 2.0 * p[i + 1].x;
        k[3] *= 2.0 * p[i + 2].x;
        Real m[4][4];
        for (int row = 0; row < 2; ++row) {
            const Real w = p[i + 1 + row].y;
            m[row][0] = w * w * w;
            m[row][1] = w * w;
            m[row][2] = w;
            m[row][3] = 1.0;
            m[2 + row][0] = 3.0 * w * w;
            m[2 + row][1] = 2.0 * w;
            m[2 + row][2] = 1.0;
            m[2 + row][3] = 0.0;
        }
        Real inv[4][4];
        if (!pov_invert_4x4(m, inv)) return "Singular matrix in MInvers";
        Real coef[4];
        for (int row = 0; row < 4; ++row) {
            coef[row] = k[0] * inv[row][0] + k[1] * inv[row][1] + k[2] * inv[row][2] +
                        k[3] * inv[row][3];
            if (std::fabs(coef[row]) < kPovEpsilon) coef[row] = 0;
        }
        const SorSpline::Segment s{coef[0], coef[1], coef[2], coef[3]};
        out.segments.push_back(s);
        // The radius range: the ends, and an extremum of r^2 inside (its square root:
        // NaN where r^2 dips below 0, which then disables the segment as in POV-Ray).
        const Real y[2] = {p[i + 1].y, p[i + 2].y};
        Real x[4] = {p[i + 1].x, p[i + 2].x, p[i + 1].x, p[i + 2].x};
        const Real slope[3] = {3.0 * s.a, 2.0 * s.b, s.c};
        Real roots[2];
        int nr = pov_solve_polynomial(2, slope, roots, false);
        while (nr--) {
            const Real h = roots[nr];
            if (h >= y[0] && h <= y[1])
                x[nr] = std::sqrt(h * (h * (h * s.a + s.b) + s.c) + s.d);
        }
        r1[i] = std::min(std::min(x[0], x[1]), std::min(x[2], x[3]));
        r2[i] = std::max(std::max(x[0], x[1]), std::max(x[2], x[3]));
        h1[i] = y[0];
        h2[i] = y[1];
        xmin = std::min(xmin, r1[i]);
        xmax = std::max(xmax, r2[i]);
        ymin = std::min(ymin, h1[i]);
        ymax = std::max(ymax, h2[i]);
    }
    out.radius1 = xmin;
    out.radius2 = xmax;
    out.height1 = ymin;
    out.height2 = ymax;
    auto squared_radius = [](const SorSpline::Segment& s, Real w) {
        return std::max(0.0, w * (w * (s.a * w + s.b) + s.c) + s.d);
    };
    out.cap_radius2 = squared_radius(out.segments.back(), h2[n - 1]);
    out.base_radius2 = squared_radius(out.segments.front(), h1[0]);
    out.cylinders = make_bounding_cylinders(r1, r2, h1, h2);
    return "";
}

}  // namespace povwall
