// A camera sample's colour as the sum of its rays' forward contributions (each ray's
// local colour times the product of the factors on its way from the camera), when the
// shading is linear (RenderPlan::parent_tracking false). Every driver sums the same
// contributions: the single-process tracer as it recurses, black boxes and workers as
// the rays arrive, in any order. Each contribution is rounded to a multiple of 2^-32
// first, so the double sums are exact (below 2^21 in size) and equal bit for bit
// whatever the order, the boxes or the processes.
#pragma once

#include <cmath>

#include "core/colour.h"

namespace povwall::trace {

inline double on_sum_grid(float v) {
    return std::nearbyint(double(v) * 0x1p32) * 0x1p-32;
}

struct ForwardSum {
    double r = 0, g = 0, b = 0, transmit = 0;
    void add(const Rgb& c, float t) {
        r += on_sum_grid(c.r);
        g += on_sum_grid(c.g);
        b += on_sum_grid(c.b);
        transmit += on_sum_grid(t);
    }
};

}  // namespace povwall::trace
