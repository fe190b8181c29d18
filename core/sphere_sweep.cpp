// POV-Ray 3.7's SphereSweep::Compute (notes: shape-sphere_sweep.md section 3): the
// segment polynomials, their end spheres and derivatives, and the joint spheres.
#include "core/scene.h"

namespace povwall {
namespace {

// The basis matrices, entries exactly the double quotients x/2 and x/6 as POV-Ray's.
constexpr Real kCatmullRom[4][4] = {{0.0 / 2, 2.0 / 2, 0.0 / 2, 0.0 / 2},
                                    {-1.0 / 2, 0.0 / 2, 1.0 / 2, 0.0 / 2},
                                    {2.0 / 2, -5.0 / 2, 4.0 / 2, -1.0 / 2},
                                    {-1.0 / 2, 3.0 / 2, -3.0 / 2, 1.0 / 2}};
constexpr Real kBSpline[4][4] = {{1.0 / 6, 4.0 / 6, 1.0 / 6, 0.0 / 6},
                                 {-3.0 / 6, 0.0 / 6, 3.0 / 6, 0.0 / 6},
                                 {3.0 / 6, -6.0 / 6, 3.0 / 6, 0.0 / 6},
                                 {-1.0 / 6, 3.0 / 6, -3.0 / 6, 1.0 / 6}};

}  // namespace

SphereSweepData make_sphere_sweep(SweepSpline spline, std::vector<SweepSphere> modeling) {
    SphereSweepData d;
    d.spline = spline;
    d.modeling = std::move(modeling);
    const std::vector<SweepSphere>& m = d.modeling;
    const int n = int(m.size());
    if (spline == SweepSpline::Linear) {
        for (int i = 0; i + 1 < n; ++i) {
            SweepSegment s;
            s.coefficients = 2;
            s.centre_coef[1] = m[i + 1].centre - m[i].centre;
            s.radius_coef[1] = m[i + 1].radius - m[i].radius;
            s.centre_coef[0] = m[i].centre;
            s.radius_coef[0] = m[i].radius;
            d.segments.push_back(s);
        }
    } else {
        const Real(*basis)[4] =
            spline == SweepSpline::CatmullRom ? kCatmullRom : kBSpline;
        for (int i = 0; i + 3 < n; ++i) {
            SweepSegment s;
            s.coefficients = 4;
            for (int k = 0; k < 4; ++k) {
                // The first term scaled, then each further one added scaled (the same
                // roundings as POV-Ray's VScale then VAddScaledEq).
                s.centre_coef[k] = m[i].centre * basis[k][0];
                s.radius_coef[k] = m[i].radius * basis[k][0];
                for (int j = 1; j < 4; ++j) {
                    s.centre_coef[k] = s.centre_coef[k] + m[i + j].centre * basis[k][j];
                    s.radius_coef[k] += basis[k][j] * m[i + j].radius;
                }
            }
            d.segments.push_back(s);
        }
    }
    for (SweepSegment& s : d.segments) {
        s.closing[0] = {s.centre_coef[0], s.radius_coef[0]};
        s.centre_deriv[0] = s.centre_coef[1];
        s.radius_deriv[0] = s.radius_coef[1];
        s.closing[1] = s.closing[0];
        for (int k = 1; k < s.coefficients; ++k) {
            s.closing[1].centre = s.closing[1].centre + s.centre_coef[k];
            s.closing[1].radius += s.radius_coef[k];
        }
        s.centre_deriv[1] = s.centre_coef[1];
        s.radius_deriv[1] = s.radius_coef[1];
        for (int k = 2; k < s.coefficients; ++k) {
            s.centre_deriv[1] = s.centre_deriv[1] + s.centre_coef[k] * Real(k);
            s.radius_deriv[1] += k * s.radius_coef[k];
        }
    }
    for (const SweepSegment& s : d.segments) d.joints.push_back(s.closing[0]);
    if (!d.segments.empty()) d.joints.push_back(d.segments.back().closing[1]);
    return d;
}

}  // namespace povwall
