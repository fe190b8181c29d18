// The quadric boxes of core/quadric.h when a clip or an intersection sibling is some
// other object: POV-Ray cuts the range by that object's own bounding box (its BBox,
// Make_min_max_from_BBox). Those boxes are trace/'s (ObjectQueries::box), so the parser
// passes them in; without a provider the functions refuse as before.
#pragma once

#include <functional>
#include <vector>

#include "core/quadric.h"
#include "core/scene.h"

namespace povwall {

using PovBoxOf = std::function<Csg::PovBox(const Object&)>;

bool quadric_clip_bounds(Quadric& q, const std::vector<Object>& clips,
                         const PovBoxOf& box_of);
bool quadric_csg_bounds_impl(std::vector<Object>& children,
                             const std::vector<bool>& inverted, const PovBoxOf& box_of);

}  // namespace povwall
