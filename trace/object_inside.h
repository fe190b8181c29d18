// POV-Ray's Inside of an object without its own clipped_by: what inside_object()
// (prepared_scene.h) tests once the clips have passed, and what a cutaway CSG asks of its
// parts (POV-Ray does not test a CSG part's own clips there).
#pragma once

#include "core/scene.h"

namespace povwall::trace {

// `inverted`: the object as POV-Ray holds it once more inverted (a difference's later
// parts, the children of an inverted CSG): its shape is, its clips are not.
bool inside_unclipped(const Object& obj, const Point3& p, bool inverted = false);
bool inside_object(const Object& obj, const Point3& p, bool inverted);

}  // namespace povwall::trace
