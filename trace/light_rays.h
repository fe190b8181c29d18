// Light reaching a point, as POV-Ray 3.7 computes it for a lit surface (its
// ComputeOneWhiteLightRay and Attenuate_Light): the direction and depth of the light ray,
// the light's colour after its cone and fade, and the shadow ray that tests it. Shared
// by the surface shading, the media's light samples and subsurface scattering.
#pragma once

#include <cstddef>

#include "trace/render_plan.h"
#include "trace/shading.h"

namespace povwall::trace {

struct LightSample {
    Vector3 dir;  // unit, from the point toward the light
    Real distance;
    Rgb colour;  // after spot, cylinder and fade attenuation
};

// POV-Ray 3.7's light groups (Trace::ComputeDiffuseLight): the global lights unless the
// object's light group turned them off, and the lights of the object's own group.
bool lights_material(const Light& light, const Material& m);

// The light ray from `p` toward light `l`'s centre and its attenuated colour; false when
// the light cannot light `p` (outside a spotlight's cone, behind a cylinder light,
// black).
bool light_at(const Light& l, const Point3& p, LightSample& s);

// Whether light `l` lights a point sample by sample: POV-Ray 3.7's area_illumination
// (its "full area lighting"), only where the area grid is used at all (from +Q5, not
// under a radiosity sample ray).
bool full_area_lighting(const Light& l, Quality quality, const TraceRay& ray);

// The light ray from `p` toward `towards` (the light's location or a sample of its area
// grid), as POV-Ray's ComputeOneWhiteLightRay: straight toward it, except that a cylinder
// light's rays, and a parallel light's, run along the line from point_at to it, the
// depth measured along them. Colour left unset; false at the point itself.
bool light_ray_toward(const Light& l, const Point3& p, const Point3& towards,
                      LightSample& s);

// POV-Ray's Attenuate_Light for the light ray `s` from `p`: a spotlight's cone read from
// that ray's direction (so per area sample), a cylinder light's from `p`'s distance to
// its axis, and the fade over the ray's depth.
float light_attenuation(const Light& l, const Point3& p, const LightSample& s);

// The shadow ray from `at` toward light `l` (sample `s`) for a ray `from` spawned it.
ChildRay shadow_child(const TraceRay& from, const Point3& at, const LightSample& s,
                      size_t l);

}  // namespace povwall::trace
