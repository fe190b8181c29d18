// POV-Ray's bounding cylinders of lathe and sor segments along a ray (its
// Intersect_BCyl): which segments the ray may meet, in the order POV-Ray tests them.
#pragma once

#include <vector>

#include "trace/shapes/common.h"

namespace povwall::trace {

struct SegmentInterval {
    Real entry;  // object distance where the ray enters the segment's thick cylinder
    uint32_t segment;
};

// The segments whose thick cylinder (between its inner and outer radius and its two
// heights) the ray from `p` along the unit `d` meets ahead, sorted by entry; a segment
// entered at an equal distance comes before the earlier ones, as POV-Ray inserts them.
void bounding_cylinder_intervals(const BoundingCylinders& b, const Point3& p,
                                 const Vector3& d, std::vector<SegmentInterval>& out);

}  // namespace povwall::trace
