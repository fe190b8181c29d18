// The interiors a camera ray starts inside of. POV-Ray gives each camera ray the
// interiors of the top-level objects (a plain union's children on their own) that
// contain its origin, before the ray is traced: a camera inside a glass sphere sees out
// through it, a camera under a sky `plane { y, 1000 }` is inside that plane (which
// changes fresnel reflection at every exit, POV-Ray's quirk, see shading.cpp).
#pragma once

#include <vector>

#include "core/scene.h"
#include "trace/shading.h"

namespace povwall::trace {

class CameraInteriors {
  public:
    explicit CameraInteriors(const Scene& scene);
    // The stack a camera ray from `origin` starts with.
    void seed(const Point3& origin, InteriorStack& out) const;

  private:
    void collect(const Object& o, const Bounds3& origins);
    void fill(const Point3& origin, InteriorStack& out) const;
    // Objects whose bounds meet the camera's ray origins, each with a stand-in material
    // naming it and its interior (stable: reserved before they are made).
    std::vector<const Object*> candidates_;
    std::vector<Bounds3> bounds_;
    std::vector<Material> materials_;
    bool per_ray_ = false;  // orthographic and cylinder 3/4: each ray has its own origin
    InteriorStack fixed_;
};

}  // namespace povwall::trace
