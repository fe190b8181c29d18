// Primitives too large for the tree: a sky sphere of radius 1e6 or a cloud shell around a
// scene a few units wide. In the octree such a box would set the root's size, and the
// depth limit would then leave the whole scene in a few crowded leaves (POV-Ray's
// benchmark.pov: its 20,000-triangle mesh in leaves of thousands, 28,000 triangle tests
// per ray). The caller tests them for every ray instead, as it does unbounded ones.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/math.h"

namespace povwall::octree {

// Whose box's diagonal exceeds the others' together this many times.
constexpr Real kGiantRatio = 64;
// At most this many (each costs every ray a test).
constexpr size_t kMaxGiants = 16;

// Indices of the giants among `bounds` (ascending): the largest k boxes, for the
// largest k <= kMaxGiants such that the smallest of them has a diagonal over kGiantRatio
// times that of the union of all the other boxes. Empty and infinite boxes are never
// giants and do not count in the union.
std::vector<uint32_t> giant_primitives(std::span<const Bounds3> bounds);

}  // namespace povwall::octree
