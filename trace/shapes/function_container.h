// The container of a function shape (isosurface, parametric: `contained_by { box |
// sphere }`) as POV-Ray 3.7 meets it: the box by Box::Intersect, the sphere by the static
// Sphere::Intersect along the unit direction, and the box both keep through their matrix.
#pragma once

#include "trace/pov_bounds.h"
#include "trace/shapes/common.h"

namespace povwall::trace {

struct FunctionContainer {
    bool sphere;
    const Point3 &corner1, &corner2, &centre;
    Real radius;
};

// The container's span along o + t d (world distances: d the object-space direction, not
// normalised) and the box faces there as POV-Ray's sides (1..6 for -x, +x, -y, +y, -z,
// +z; 0: none, and always 0 for the sphere). The sphere's t1 may be negative.
bool container_span(const FunctionContainer& c, const Point3& o, const Vector3& d,
                    Real& t1, Real& t2, int& side1, int& side2);
Bounds3 container_bounds(const FunctionContainer& c);
// The container's box through the object's matrix (these shapes always have one).
PovBBox container_pov_bbox(const FunctionContainer& c, const CompactTransform& xf);

}  // namespace povwall::trace
