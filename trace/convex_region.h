// The bounds of a convex region: a box cut by half-spaces. A CSG intersection of planes
// (a prism, a gem, a twisted column's slices) has a finite surface although every plane
// on its own is infinite; without these bounds it would be tested by every ray.
#pragma once

#include <span>

#include "core/math.h"

namespace povwall::trace {

// The points p with dot(normal, p) <= offset.
struct HalfSpace {
    Vector3 normal;
    Real offset = 0;
};

// A box holding every point of `box` (whose sides may be infinite) that lies in all of
// `cuts`: each side as tight as the cuts make it, padded beyond the rounding of the
// vertices it comes from, and infinite where the cuts leave the region open that way.
// `box` itself where the answer is not sure to hold everything (more than
// kMaxConvexCuts cuts, or no vertex found).
constexpr size_t kMaxConvexCuts = 24;
Bounds3 convex_region_bounds(const Bounds3& box, std::span<const HalfSpace> cuts);

}  // namespace povwall::trace
