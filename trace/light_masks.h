// `light_source { projected_through { OBJECT } }`: the light reaches a point only through
// its object (POV-Ray 3.7's Trace::TracePointLightShadowRay). The object is not part of
// the scene: it casts no shadow and is never seen; each light's is prepared on its own.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "core/math.h"
#include "core/scene.h"

namespace povwall::trace {

class PreparedScene;

class LightMasks {
  public:
    // One prepared object per light that has one; empty() when no light has.
    explicit LightMasks(const Scene& scene);
    ~LightMasks();
    LightMasks(const LightMasks&) = delete;
    LightMasks& operator=(const LightMasks&) = delete;

    bool empty() const { return lights_with_masks_ == 0; }

    // Whether light `light` reaches `at` along the unit `to_light` (the light `distance`
    // away): POV-Ray's rule, only when shadows are on (+Q4 and up). Its object's nearest
    // crossing at depth >= 1e-4 on that whole line (Find_Intersection) must lie nearer
    // than the light; then only what lies before that crossing can shadow the point:
    // `blockers_end` is the crossing's depth (the shadow ray's new light distance:
    // blockers in (1e-3, crossing - 1e-3), as POV-Ray's projectedDepth gives). A light
    // without an object reaches the point with blockers_end = distance.
    bool reaches(size_t light, const Point3& at, const Vector3& to_light, Real distance,
                 Real& blockers_end) const;

  private:
    struct Mask;
    std::vector<std::unique_ptr<Mask>> per_light_;  // null: the light has none
    size_t lights_with_masks_ = 0;
    uint64_t id_;  // names this set for the per-thread contexts
};

}  // namespace povwall::trace
