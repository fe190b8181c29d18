// The inverse of a 4x4 matrix by cofactors over the determinant, each 3x3 minor as the
// six triple products of the rule of Sarrus, in the order POV-Ray 3.7's MInvers sums
// them. POV-Ray inverts a `matrix` transform and each sor segment's Hermite system this
// way; another method rounds differently, and rays turned into a sor or lathe met
// edge-on then meet other round-off roots.
#pragma once

#include "core/math.h"

namespace povwall {

// r = m^-1 (row-vector convention or not: the same numbers). False when singular.
bool pov_invert_4x4(const Real m[4][4], Real r[4][4]);

}  // namespace povwall
