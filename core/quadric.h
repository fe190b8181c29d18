// A quadric's world coefficients and POV-Ray's box for it, as POV-Ray 3.7 keeps them
// (notes: shape-poly-quadric.md 1.8, 6.2, 6.3): each transform step is folded into the
// ten coefficients and moves the box; the box itself comes from the coefficients only
// when Compute_BBox runs (at parse time, with its two known bugs).
#pragma once

#include "core/scene.h"

namespace povwall {

// The quadric after one transform step (POV-Ray rounds the coefficients step by step):
// Q(p M^-1), then its box moved as a box (Recompute_BBox).
void quadric_transform(Quadric& q, const Transform& t);
// POV-Ray's Quadric::Compute_BBox(ClipMin, ClipMax) without clip objects, on the current
// coefficients: a box from the surface's kind (ellipsoid, cylinder, cone, hyperboloid,
// paraboloid, with POV-Ray's wrong paraboloid centre and its hyperboloid radius for
// |J| = 1), within the clip range, kept when smaller than the current box.
void quadric_compute_bbox(Quadric& q, const Vector3& clip_min, const Vector3& clip_max);

}  // namespace povwall
