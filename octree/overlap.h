// Exact cell/primitive overlap predicates for BuildInput::overlaps. Cells are closed
// boxes: touching counts. The answers are exact for the primitives as given in doubles
// (no tolerance); they are implemented with CGAL (octree/overlap.cpp, the only
// translation unit that includes CGAL) and are safe to call from several build threads at
// once.
#pragma once

#include "core/math.h"

namespace povwall::octree {

/// Ball of centre `c` and radius `r` (r >= 0) against the closed box `cell`.
bool sphere_overlaps(const Point3& c, Real r, const Bounds3& cell);
/// Closed box `b` against `cell`.
bool box_overlaps(const Bounds3& b, const Bounds3& cell);
/// Triangle (a, b, c), possibly degenerate, against `cell`.
bool triangle_overlaps(const Point3& a, const Point3& b, const Point3& c,
                       const Bounds3& cell);
/// The same answer from CGAL alone (triangle_overlaps decides most cases in doubles
/// first); tests compare the two.
bool triangle_overlaps_exactly(const Point3& a, const Point3& b, const Point3& c,
                               const Bounds3& cell);

}  // namespace povwall::octree
