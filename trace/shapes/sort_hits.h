// Sorting a shape's hits by depth without an allocation per ray.
#pragma once

#include "trace/shapes/common.h"

namespace povwall::trace {

// Sorts out[first..] by depth, equal depths kept in their order: std::stable_sort's
// result, without the temporary buffer it allocates on every call (a shape's few hits
// per ray are sorted in place; a NaN depth or many hits take std::stable_sort itself).
void stable_sort_by_depth(ShapeHits& out, size_t first);

}  // namespace povwall::trace
