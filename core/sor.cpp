// The spline of a surface of revolution (scene.h), as POV-Ray's Compute_Sor builds it.
#include <algorithm>
#include <cmath>

#include "core/pov_polysolve.h"
#include "core/scene.h"

namespace povwall {

namespace {

constexpr Real kEpsilon = 1e-10;

// The inverse of m by cofactors over the determinant, in POV-Ray's arithmetic (its
// MInvers): the coefficients then round as POV-Ray's do. False when singular.
bool invert_by_cofactors(const Real m[4][4], Real r[4][4]) {
    const Real m00 = m[0][0], m01 = m[0][1], m02 = m[0][2], m03 = m[0][3];
    const Real m10 = m[1][0], m11 = m[1][1], m12 = m[1][2], m13 = m[1][3];
    const Real m20 = m[2][0], m21 = m[2][1], m22 = m[2][2], m23 = m[2][3];
    const Real m30 = m[3][0], m31 = m[3][1], m32 = m[3][2], m33 = m[3][3];
    // The 3x3 minors, each as six triple products (the rule of Sarrus).
    auto minor = [](Real a0, Real a1, Real a2, Real b0, Real b1, Real b2, Real c0,
                    Real c1, Real c2) {
        return a0 * b1 * c2 + a1 * b2 * c0 + a2 * b0 * c1 - c0 * b1 * a2 - c1 * b2 * a0 -
               c2 * b0 * a1;
    };
    const Real d00 = minor(m11, m12, m13, m21, m22, m23, m31, m32, m33);
    const Real d01 = minor(m10, m12, m13, m20, m22, m23, m30, m32, m33);
    const Real d02 = minor(m10, m11, m13, m20, m21, m23, m30, m31, m33);
    const Real d03 = minor(m10, m11, m12, m20, m21, m22, m30, m31, m32);
    const Real d10 = minor(m01, m02, m03, m21, m22, m23, m31, m32, m33);
    const Real d11 = minor(m00, m02, m03, m20, m22, m23, m30, m32, m33);
    const Real d12 = minor(m00, m01, m03, m20, m21, m23, m30, m31, m33);
    const Real d13 = minor(m00, m01, m02, m20, m21, m22, m30, m31, m32);
    const Real d20 = minor(m01, m02, m03, m11, m12, m13, m31, m32, m33);
    const Real d21 = minor(m00, m02, m03, m10, m12, m13, m30, m32, m33);
    const Real d22 = minor(m00, m01, m03, m10, m11, m13, m30, m31, m33);
    const Real d23 = minor(m00, m01, m02, m10, m11, m12, m30, m31, m32);
    const Real d30 = minor(m01, m02, m03, m11, m12, m13, m21, m22, m23);
    const Real d31 = minor(m00, m02, m03, m10, m12, m13, m20, m22, m23);
    const Real d32 = minor(m00, m01, m03, m10, m11, m13, m20, m21, m23);
    const Real d33 = minor(m00, m01, m02, m10, m11, m12, m20, m21, m22);
    const Real det = m00 * d00 - m01 * d01 + m02 * d02 - m03 * d03;
    if (det == 0) return false;
    const Real d[4][4] = {{d00, d01, d02, d03},
                          {d10, d11, d12, d13},
                          {d20, d21, d22, d23},
                          {d30, d31, d32, d33}};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r[i][j] = ((i + j) % 2 ? -d[j][i] : d[j][i]) / det;
    return true;
}

}  // namespace

std::string make_sor_spline(const std::vector<ProfilePoint>& p, SorSpline& out) {
    const size_t n = p.size() - 3;
    out = SorSpline{};
    std::vector<Real> r1(n), r2(n), h1(n), h2(n);
    Real xmin = 2e10, xmax = -2e10, ymin = 2e10, ymax = -2e10;
    for (size_t i = 0; i < n; ++i) {
        if (std::fabs(p[i + 2].y - p[i].y) < kEpsilon ||
            std::fabs(p[i + 3].y - p[i + 1].y) < kEpsilon)
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
        if (!invert_by_cofactors(m, inv)) return "Singular matrix in MInvers";
        Real coef[4];
        for (int row = 0; row < 4; ++row) {
            coef[row] = k[0] * inv[row][0] + k[1] * inv[row][1] + k[2] * inv[row][2] +
                        k[3] * inv[row][3];
            if (std::fabs(coef[row]) < kEpsilon) coef[row] = 0;
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
