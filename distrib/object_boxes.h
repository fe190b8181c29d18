// Which boxes an object is placed in: those its world bounds overlap. The one test every
// process makes (the in-process boxes, the coordinator counting each worker's objects, a
// worker keeping only its part of the scene), so they all agree on where an object is.
#pragma once

#include <algorithm>
#include <limits>
#include <vector>

#include "core/scene.h"
#include "distrib/virtual_walls.h"
#include "trace/prepared_scene.h"

namespace povwall::distrib {

inline std::vector<int> boxes_of_object(const VirtualWalls& walls, const Object& object) {
    return walls.boxes_overlapping(trace::object_world_bounds(object));
}

// A box holding an object whose surface can lie outside its POV-Ray box
// (trace::pov_walk_reach), and the hull where rays must be followed to decide whether
// POV-Ray sees it: the box holds every object that overlaps the hull as well, so its
// PreparedScene can look past its wall (PreparedScene::closest_hit).
struct WalkReach {
    int box = 0;
    Bounds3 hull;
};

inline std::vector<WalkReach> walk_reaches(const VirtualWalls& walls,
                                           const Scene& scene) {
    std::vector<WalkReach> reaches;
    for (const Object& o : scene.objects) {
        const Bounds3 hull = trace::pov_walk_reach(o);
        if (hull.empty()) continue;
        for (int b : boxes_of_object(walls, o)) reaches.push_back({b, hull});
    }
    return reaches;
}

// The boxes that hold `object`: those it overlaps (`boxes`, from boxes_of_object), and
// those whose walk reaches it overlaps. Ascending.
inline std::vector<int> boxes_holding(std::vector<int> boxes, const Object& object,
                                      const std::vector<WalkReach>& reaches) {
    if (reaches.empty()) return boxes;
    const Bounds3 bounds = trace::object_world_bounds(object);
    for (const WalkReach& r : reaches)
        if (!intersection(bounds, r.hull).empty()) boxes.push_back(r.box);
    std::sort(boxes.begin(), boxes.end());
    boxes.erase(std::unique(boxes.begin(), boxes.end()), boxes.end());
    return boxes;
}
inline std::vector<int> boxes_holding(const VirtualWalls& walls, const Object& object,
                                      const std::vector<WalkReach>& reaches) {
    return boxes_holding(boxes_of_object(walls, object), object, reaches);
}

}  // namespace povwall::distrib
