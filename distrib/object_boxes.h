// Which boxes an object is placed in: those its world bounds overlap. The one test every
// process makes (the in-process boxes, the coordinator counting each worker's objects, a
// worker keeping only its part of the scene), so they all agree on where an object is.
#pragma once

#include <vector>

#include "core/scene.h"
#include "distrib/virtual_walls.h"
#include "trace/prepared_scene.h"

namespace povwall::distrib {

inline std::vector<int> boxes_of_object(const VirtualWalls& walls, const Object& object) {
    return walls.boxes_overlapping(trace::object_world_bounds(object));
}

}  // namespace povwall::distrib
