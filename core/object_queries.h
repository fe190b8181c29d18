// What the scene language asks of an object while parsing: trace(), inside(),
// min_extent() and max_extent() (and the box a CSG keeps from the moment it is closed).
// The shapes live in trace/, which the parser cannot call: the commands pass
// trace::parse_time_object_queries(), and without it those functions stop with
// `unsupported:`.
#pragma once

#include <memory>
#include <optional>

#include "core/math.h"
#include "core/scene.h"

namespace povwall {

class ObjectQueries {
  public:
    virtual ~ObjectQueries() = default;
    struct Hit {
        Point3 point;
        Vector3 normal;  // the hit leaf's normal, reversed when that leaf is inverted
    };
    // POV-Ray's Find_Intersection: the nearest hit at distance >= 1e-4 along the ray from
    // `origin` in the unit direction `direction`, or nothing. The object is held (the
    // answer may be cached for the next call on the same object).
    virtual std::optional<Hit> trace(const std::shared_ptr<Object>& object,
                                     const Point3& origin, const Vector3& direction) = 0;
    // POV-Ray's Inside_Object: inside every clipped_by object and inside the shape.
    virtual bool inside(const std::shared_ptr<Object>& object, const Point3& p) = 0;
    // POV-Ray's bounding box of the object: lower-left corner and lengths in single
    // precision (min_extent reads the corner, max_extent corner + lengths in float).
    virtual Csg::PovBox box(const Object& object) = 0;
};

}  // namespace povwall
