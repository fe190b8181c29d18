// functions.inc's internal functions (`function { internal(N) }`, N = 0 ... 78), computed
// as POV-Ray 3.7 computes them: the same formulas in the same arithmetic order, so the
// values are equal bit for bit.
#pragma once

#include "core/function.h"

namespace povwall {

// internal(n) at x, y, z = a[0], a[1], a[2] and its internal_extra(n) parameters after
// them.
double internal_function(int n, const double* a, const FunctionHooks& hooks);

}  // namespace povwall
