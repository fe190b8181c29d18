// POV-Ray's Inside of an object without its own clipped_by: what inside_object()
// (prepared_scene.h) tests once the clips have passed, and what a cutaway CSG asks of its
// parts (POV-Ray does not test a CSG part's own clips there).
#pragma once

#include "core/scene.h"

namespace povwall::trace {

bool inside_unclipped(const Object& obj, const Point3& p);

}  // namespace povwall::trace
