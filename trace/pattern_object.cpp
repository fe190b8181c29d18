// The object pattern (`object { OBJ }`): 1 inside the object, 0 outside, as POV-Ray's
// object_pattern asks Inside_Object (clips and inverse included) at the pattern's point.
#include "trace/pattern_internal.h"
#include "trace/prepared_scene.h"

namespace povwall::trace::detail {

bool inside_pattern_object(const Object& object, const Point3& p) {
    return inside_object(object, p);
}

}  // namespace povwall::trace::detail
