// The bounds POV-Ray 3.7 puts on a parametric's coordinate functions over a uv rectangle
// (fpmetric.cpp's Evaluate_Function_Interval_UV and Precompute_Parametric_Values), shared
// by the parser's precompute and the tracer's subdivision (trace/shapes/parametric.h).
#pragma once

#include "core/function.h"
#include "core/scene.h"

namespace povwall {

// A coordinate function at (u, v): the function's first two parameters (x, y; u and v
// read them), the third 0.
Real parametric_coordinate(const FunctionProgram& f, const FunctionHooks& hooks, Real u,
                           Real v);

// [low, high] bounding f - accuracy over [u0, u1] x [v0, v1], with max_gradient as the
// slope limit: the corners' values widened along the two v edges, then across u (the
// offset 0 where the corners already differ by more than the slope allows). POV-Ray
// subtracts `accuracy` from the values (its interval code takes it as a threshold).
void parametric_interval(const FunctionProgram& f, const FunctionHooks& hooks,
                         Real accuracy, Real max_gradient, Real u0, Real v0, Real u1,
                         Real v1, Real& low, Real& high);

// The precompute tree: sector 1 is the whole rectangle, sector s splits (the longer side,
// u on a tie, at the midpoint) into 2s (lower half) and 2s + 1; the 2^(depth-1) leaves
// hold parametric_interval's bounds, every other sector the union of its two halves'.
// `depth` must be in [1, 20] (POV-Ray's limit).
ParametricPrecompute make_parametric_precompute(const Parametric& p, const bool axis[3],
                                                int depth, const FunctionHooks& hooks);

}  // namespace povwall
