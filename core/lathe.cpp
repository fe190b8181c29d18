// The spline of a lathe (scene.h), as POV-Ray's Compute_Lathe builds it.
#include <algorithm>

#include "core/pov_polysolve.h"
#include "core/scene.h"

namespace povwall {

namespace {

// The cubic's value at t, as POV-Ray evaluates it.
Real cubic_at(Real a, Real b, Real c, Real d, Real t) {
    return t * (t * (t * a + b) + c) + d;
}

// Where a quadratic or cubic segment's coordinate has an extremum inside (0 <= t <= 1),
// its value replaces the end values in ends[0] or ends[1] (by root number, as POV-Ray).
void widen_by_extrema(Real a, Real b, Real c, Real d, Real ends[4]) {
    const Real slope[3] = {3.0 * a, 2.0 * b, c};
    Real roots[2];
    int n = pov_solve_polynomial(2, slope, roots, false);
    while (n--)
        if (roots[n] >= 0.0 && roots[n] <= 1.0) ends[n] = cubic_at(a, b, c, d, roots[n]);
}

}  // namespace

LatheSpline make_lathe_spline(LatheSplineKind kind, const std::vector<ProfilePoint>& p) {
    LatheSpline out;
    out.kind = kind;
    const size_t count = p.size();
    const size_t segments = kind == LatheSplineKind::Linear      ? count - 1
                            : kind == LatheSplineKind::Quadratic ? count - 2
                            : kind == LatheSplineKind::Cubic     ? count - 3
                                                                 : count / 4;
    std::vector<Real> r1, r2, h1, h2;
    Real xmin = 2e10, xmax = -2e10, ymin = 2e10, ymax = -2e10;
    for (size_t s = 0, i = 0; s < segments; ++s) {
        // The same interpolation of both coordinates; x[] and y[] the values bounding
        // the segment.
        Real coef[2][4], ends[2][4];
        for (int axis = 0; axis < 2; ++axis) {
            auto at = [&](size_t k) { return axis == 0 ? p[k].x : p[k].y; };
            Real* c = coef[axis];
            Real* e = ends[axis];
            switch (kind) {
                case LatheSplineKind::Linear:
                    c[0] = 0.0;
                    c[1] = 0.0;
                    c[2] = -1.0 * at(i) + 1.0 * at(i + 1);
                    c[3] = 1.0 * at(i);
                    e[0] = e[2] = at(i);
                    e[1] = e[3] = at(i + 1);
                    break;
                case LatheSplineKind::Quadratic:
                    c[0] = 0.0;
                    c[1] = 0.5 * at(i) - 1.0 * at(i + 1) + 0.5 * at(i + 2);
                    c[2] = -0.5 * at(i) + 0.5 * at(i + 2);
                    c[3] = 1.0 * at(i + 1);
                    e[0] = e[2] = at(i + 1);
                    e[1] = e[3] = at(i + 2);
                    break;
                case LatheSplineKind::Cubic:  // Catmull-Rom through the middle two points
                    c[0] = -0.5 * at(i) + 1.5 * at(i + 1) - 1.5 * at(i + 2) +
                           0.5 * at(i + 3);
                    c[1] = at(i) - 2.5 * at(i + 1) + 2.0 * at(i + 2) - 0.5 * at(i + 3);
                    c[2] = -0.5 * at(i) + 0.5 * at(i + 2);
                    c[3] = at(i + 1);
                    e[0] = e[2] = at(i + 1);
                    e[1] = e[3] = at(i + 2);
                    break;
                case LatheSplineKind::Bezier:
                    c[0] = at(i + 3) - 3.0 * at(i + 2) + 3.0 * at(i + 1) - at(i);
                    c[1] = 3.0 * at(i + 2) - 6.0 * at(i + 1) + 3.0 * at(i);
                    c[2] = 3.0 * at(i + 1) - 3.0 * at(i);
                    c[3] = at(i);
                    for (int k = 0; k < 4; ++k) e[k] = at(i + k);  // the control points
                    break;
            }
            if (kind == LatheSplineKind::Quadratic || kind == LatheSplineKind::Cubic)
                widen_by_extrema(c[0], c[1], c[2], c[3], e);
        }
        out.segments.push_back({coef[0][0], coef[0][1], coef[0][2], coef[0][3],
                                coef[1][0], coef[1][1], coef[1][2], coef[1][3]});
        const Real* x = ends[0];
        const Real* y = ends[1];
        r1.push_back(std::min(std::min(x[0], x[1]), std::min(x[2], x[3])));
        r2.push_back(std::max(std::max(x[0], x[1]), std::max(x[2], x[3])));
        h1.push_back(std::min(std::min(y[0], y[1]), std::min(y[2], y[3])));
        h2.push_back(std::max(std::max(y[0], y[1]), std::max(y[2], y[3])));
        xmin = std::min(xmin, r1.back());
        xmax = std::max(xmax, r2.back());
        ymin = std::min(ymin, h1.back());
        ymax = std::max(ymax, h2.back());
        i += kind == LatheSplineKind::Bezier ? 4 : 1;
    }
    out.radius1 = xmin;
    out.radius2 = xmax;
    out.height1 = ymin;
    out.height2 = ymax;
    out.cylinders = make_bounding_cylinders(r1, r2, h1, h2);
    return out;
}

}  // namespace povwall
