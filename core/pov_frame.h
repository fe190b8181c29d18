// POV-Ray's Compute_Coordinate_Transform (3.7:source/backend/math/matrices.cpp): the
// frame of a cylinder, cone, disc or blob cylinder. Its unit shape (axis z from 0 to 1,
// radius 1) is scaled by (radius, radius, length), turned about (-up.y, up.x, 0) by
// acos(up.z) so that z goes to `up` (about x when up is within 1e-10 of +-z), and moved
// to `origin`; each step composed as POV-Ray composes them, so a ray meets the shape in
// the unit shape's space with POV-Ray's bits.
#pragma once

#include "core/math.h"

namespace povwall {

// `up` must be of unit length.
Transform pov_coordinate_transform(const Point3& origin, Vector3 up, Real radius,
                                   Real length);

}  // namespace povwall
