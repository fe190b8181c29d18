// POV-Ray 3.7's polynomial solving as its shapes use it (Solve_Polynomial): which method
// a degree gets, and each method's own rules. The roots these give decide silhouettes
// (a grazing ray's single quadratic root, the Sturm bracket [0, 1e7]), so shapes that
// solve as POV-Ray does call this rather than trace/roots.h.
#pragma once

#include "core/math.h"

namespace povwall::trace {

// The highest degree pov_solve_polynomial takes (POV-Ray 3.7's MAX_ORDER).
constexpr int kPovMaxOrder = 35;

// Real roots of c[0] x^n + c[1] x^(n-1) + ... + c[n] (highest power first), in the order
// POV-Ray's solvers give them (callers walk them last to first). Leading coefficients
// below 1e-10 are dropped first. Degree 1 and 2 closed form (a discriminant within 1e-10
// of 0 gives one root); 3 and 4 closed form (Vieta's quartic), or Sturm sequences when
// `sturm` is set (degree 4 also when its coefficients span more than 1e12); 5 and more
// Sturm always, which finds only roots in [0, 1e7]. `eps` > 0 drops a constant term that
// small against the linear one, for degrees 3 and 4 (POV-Ray's root elimination).
// `roots` must hold n values.
int pov_solve_polynomial(int n, const Real* c, Real* roots, bool sturm, Real eps = 0);

// The methods on their own (monic or not as stated), for tests.
int pov_solve_quadratic(const Real c[3], Real roots[2]);
int pov_solve_cubic(const Real c[4], Real roots[3]);
int pov_solve_quartic(const Real c[5], Real roots[4]);
// Sturm sequences over [0, 1e7] (POV-Ray's polysolve), c highest power first, c[0] != 0.
int pov_sturm_roots(int n, const Real* c, Real* roots);

}  // namespace povwall::trace
