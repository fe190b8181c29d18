#include "trace/shapes/function_container.h"

#include <cmath>

#include "trace/shapes/box.h"

namespace povwall::trace {

bool container_span(const FunctionContainer& c, const Point3& o, const Vector3& d,
                    Real& t1, Real& t2, int& side1, int& side2) {
    side1 = side2 = 0;
    if (!c.sphere) {
        int f1, f2;
        if (!box_span_pov(c.corner1, c.corner2, o, d, t1, t2, f1, f2)) return false;
        side1 = f1 + 1;
        side2 = f2 + 1;
        return true;
    }
    // Sphere::Intersect along the unit direction, then back to world distances.
    const Real len = length(d);
    const Vector3 u = d * (1.0 / len);
    const Vector3 oc = c.centre - o;
    const Real oc2 = dot(oc, oc);
    const Real tca = dot(oc, u);
    const Real r2 = c.radius * c.radius;
    if (oc2 >= r2 && tca < kPovEpsilon) return false;
    const Real h2 = r2 - oc2 + tca * tca;
    if (!(h2 > kPovEpsilon)) return false;
    const Real h = std::sqrt(h2);
    t1 = (tca - h) / len;
    t2 = (tca + h) / len;
    return true;
}

Bounds3 container_bounds(const FunctionContainer& c) {
    if (c.sphere) return {c.centre - Vector3(c.radius), c.centre + Vector3(c.radius)};
    return {c.corner1, c.corner2};
}

PovBBox container_pov_bbox(const FunctionContainer& c, const CompactTransform& xf) {
    PovBBox b;
    for (int a = 0; a < 3; ++a) {
        if (c.sphere) {
            b.lo[a] = float(c.centre[a] - c.radius);
            b.len[a] = float(c.radius * 2);
        } else {
            b.lo[a] = float(c.corner1[a]);
            b.len[a] = float(c.corner2[a] - c.corner1[a]);
        }
    }
    return pov_bbox(pov_corners_bounds(pov_bbox_bounds(b),
                                       [&](const Point3& p) { return xf.point(p); }));
}

}  // namespace povwall::trace
