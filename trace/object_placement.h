// Where the octree places a general object (one test_primitive asks its shape about):
// tighter than the world bounds of its box where the shape allows. A lathe turned about
// its axis fills up to twice the cells its shape can reach with those bounds alone, and a
// ray in each of them pays a candidate's tests.
#pragma once

#include "core/scene.h"

namespace povwall::trace {

// The world bounds of a frame-level general object for the octree, given its world
// bounds `world` (those of its box): a shape turned about its own y axis (lathe, sor)
// lies in the cylinder its box holds, whose bounds are narrower when the object is
// turned about another axis or its y axis is tilted. Everything else: `world`.
Bounds3 object_placement_bounds(const Object& o, const Bounds3& world);

}  // namespace povwall::trace
