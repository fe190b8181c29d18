// Polynomial root solvers: a cancellation-free quadratic (cylinders and cones not in
// POV-Ray's unit form), POV-Ray's cubic split, and quartics by two methods (closed form
// and Sturm isolation) behind a measured switch rule, which bench/roots_accuracy compares
// with POV-Ray's own solver (docs/numerics.md).
#pragma once

#include "core/math.h"

namespace povwall::trace {

// Roots of a x^2 + b x + c in ascending order, computed without cancellation.
int solve_quadratic(Real a, Real b, Real c, Real roots[2]);
// The textbook (-b ± sqrt(disc)) / 2a, kept only as the baseline of the accuracy table.
int solve_quadratic_naive(Real a, Real b, Real c, Real roots[2]);

// Real roots of x^3 + a x^2 + b x + c by the trigonometric / Cardano closed form,
// unsorted: three when r^2 <= q^3 (q = (a^2 - 3b)/9, r = (2a^3 - 9ab + 27c)/54), else
// one; none when q = r = 0 (the closed form's 0/0). The split POV-Ray's cubic solver
// makes, so a cubic it solves has as many roots here.
int solve_cubic(Real a, Real b, Real c, Real roots[3]);

// Quartics: c[i] is the coefficient of x^i, c[4] != 0. Real roots, ascending.
// Ferrari's closed form through the resolvent cubic, then per root Newton steps while
// they lower the residual: plain Horner, or compensated Horner (residual as in
// double-double).
enum class QuarticPolish { None, Newton, CompensatedNewton };
int solve_quartic_ferrari(const Real c[5], Real roots[4],
                          QuarticPolish polish = QuarticPolish::CompensatedNewton);
// Sturm-sequence isolation of the roots in (lo, hi], then bracketed Newton.
int solve_quartic_sturm(const Real c[5], Real lo, Real hi, Real roots[4]);

// povwall's own quartic, roots in (lo, hi]: Ferrari with plain Newton polishing, falling
// back to Sturm when the closed form's root count is odd (impossible for real
// coefficients); on ray-torus quartics as accurate as double-precision Sturm and ~4x
// faster (docs/numerics.md). The tracer's torus no longer uses it (it solves POV-Ray's
// quartic with POV-Ray's solver, core/pov_polysolve.h); the quartics stay as the
// accuracy benchmark's reference methods.
int solve_quartic(const Real c[5], Real lo, Real hi, Real roots[4]);

}  // namespace povwall::trace
