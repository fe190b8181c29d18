// POV-Ray 3.7's polynomial solver (Solve_Polynomial), written from its described
// behaviour (notes: shape-common.md C3) for the shapes whose pixels depend on it: which
// degree after dropping tiny leading coefficients, closed form or Sturm, the root
// elimination, the [0, 1e7] bracket of its Sturm bisection, its tolerances and its
// quirks (a near-zero quadratic discriminant gives one root; the cubic's 0/0 gives NaN).
// povwall's own solvers (roots.h) are more accurate; these give the same roots as
// POV-Ray, which decides which grazing rays hit.
#pragma once

#include "core/math.h"

namespace povwall {

// The largest degree POV-Ray 3.7 solves (its MAX_ORDER, for poly).
constexpr int kPovMaxOrder = 35;

// Real roots of c[0] x^n + ... + c[n] (highest power first, n <= kPovMaxOrder), in
// POV-Ray's order, into roots[0..n-1]. `sturm` selects Sturm bisection for degrees 3
// and 4; `root_elimination` > 0 drops the constant term when it is below that fraction
// of the linear one (a root near 0). Sturm only returns roots in [0, 1e7]; with
// `wanted` below that, it may leave out roots above `wanted` (the caller drops them) and
// returns the others exactly as POV-Ray (in its order, without the left-out ones).
int pov_solve_polynomial(int n, const Real* c, Real* roots, bool sturm,
                         Real root_elimination = 0, Real wanted = 1e7);

}  // namespace povwall
