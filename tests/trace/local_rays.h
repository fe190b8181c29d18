// Rays in a shape's own space for the shape tests (tests/trace/shape_*_test.cpp).
#pragma once

#include "trace/shapes/common.h"

namespace povwall::trace {

// From `o` along `d` (of any length) for a shape without a transform: the world ray.
inline LocalRay untransformed_ray(Point3 o, Vector3 d) {
    const Real len = length(d);
    return {o, d, d * (1.0 / len), len, false};
}

// From `o` along `d` (of any length) through a shape's transform.
inline LocalRay transformed_ray(Point3 o, Vector3 d) {
    const Real len = length(d);
    return {o, d, d * (1.0 / len), len, true};
}

}  // namespace povwall::trace
