// POV-Ray's bounding-slab test of a box (slab_tree_entry, trace/pov_bounds.h), inline:
// the leaf loops of trace/prepared_scene.cpp run it on every candidate, and most fail it.
#pragma once

#include "trace/pov_bounds.h"
#include "trace/shapes/common.h"

namespace povwall::trace {

inline bool slab_test(const PovBBox& box, const PovRay& ray, Real& entry) {
    // The entry and exit distances of one axis: the near corner's distance in float, the
    // far one that plus the length's (a float product) in double.
    auto slab = [&](int a, Real& enter, Real& leave) {
        const float base = (box.lo[a] - ray.origin[a]) * ray.inv[a];
        const Real other = Real(base) + Real(box.len[a] * ray.inv[a]);
        if (ray.inv[a] > 0) {
            enter = base;
            leave = other;
        } else {
            leave = base;
            enter = other;
        }
    };
    auto outside = [&](int a) {
        return ray.origin[a] < box.lo[a] || ray.origin[a] > box.len[a] + box.lo[a];
    };
    Real lo = -kBoundHuge, hi = kBoundHuge;
    // x opens the interval; a box behind the origin or an empty slab ends the test.
    if (ray.nonzero[0]) {
        slab(0, lo, hi);
        if (hi < kPovEpsilon || lo > hi) return false;
    } else if (outside(0)) {
        return false;
    }
    // y and z narrow it, each bound replaced only when the new one is tighter (so a NaN
    // slab changes nothing, as in POV-Ray).
    for (int a = 1; a < 3; ++a) {
        if (!ray.nonzero[a]) {
            if (outside(a)) return false;
            continue;
        }
        Real enter, leave;
        slab(a, enter, leave);
        if (leave < hi) {
            if (leave < kPovEpsilon) return false;
            if (enter > lo) {
                if (enter > leave) return false;
                lo = enter;
            } else if (lo > leave) {
                return false;
            }
            hi = leave;
        } else if (enter > lo) {
            if (enter > hi) return false;
            lo = enter;
        }
    }
    entry = lo;
    return true;
}

inline bool slab_test(const PovBBox& box, const PovRay& ray) {
    Real entry;
    return slab_test(box, ray, entry);
}

}  // namespace povwall::trace
