// Primitives numbered along a Z-order (Morton) curve: neighbours in space become
// neighbours in memory, so a ray's candidates in consecutive octree leaves share cache
// lines. Matters once the scene outgrows the caches (1e5-1e6 primitives).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/math.h"

namespace povwall::octree {

// The indices of `bounds` sorted by the Morton code of their centres (21 bits per axis
// over the union of the bounds); ties keep input order. Infinite bounds go last.
std::vector<uint32_t> morton_order(std::span<const Bounds3> bounds);

}  // namespace povwall::octree
