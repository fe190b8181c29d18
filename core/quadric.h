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

// Compute_BBox after a quadric's clipped_by list is read: the non-inverted clip objects
// cut the range (a plane by Compute_Plane_Min_Max, a quadric or an untransformed box by
// its box). False (nothing changed) for other clip objects, whose POV-Ray boxes the
// parser does not know.
bool quadric_clip_bounds(Quadric& q, const std::vector<Object>& clips);

// CSG::Compute_BBox of an intersection (or difference) for its quadrics: the running
// range starts at BOUND_HUGE each way and is cut by every non-inverted non-quadric
// child (an axis-aligned plane by its half-space, Compute_Plane_Min_Max), then each
// non-inverted quadric in turn gets Compute_BBox(range) and cuts the range by its new
// box. False (nothing changed) when a non-inverted child is neither a plane, a quadric
// nor a height field: povwall's parser does not know POV-Ray's boxes of the others.
// `inverted(i)` says whether POV-Ray sees child i inverted.
template <class Inverted>
bool quadric_csg_bounds(std::vector<Object>& children, Inverted&& inverted);
bool quadric_csg_bounds_impl(std::vector<Object>& children,
                             const std::vector<bool>& inverted);
template <class Inverted>
bool quadric_csg_bounds(std::vector<Object>& children, Inverted&& inverted) {
    std::vector<bool> flags(children.size());
    for (size_t i = 0; i < children.size(); ++i) flags[i] = inverted(i);
    return quadric_csg_bounds_impl(children, flags);
}

}  // namespace povwall
