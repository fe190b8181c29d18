// The render plan: what a scene can really use, decided once after parsing, so that the
// stages it cannot use are left out (no rays, no tables, no tree) and `--explain` can say
// so.
//
// Every decision here must leave the image unchanged: `everything_on` turns all of them
// off and the tests compare both images exactly (tests/trace/render_plan_test.cpp).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "core/scene.h"

namespace povwall::trace {

struct LightPlan {
    // Shadow rays toward this light; false when the light is shadowless or nothing in the
    // scene can stand between a lit point and the light (its result would always be 1).
    bool shadow_rays = true;
    // True when the shadow child is still spawned but known to be unoccluded (traced as 1
    // without a query), which keeps the shading arithmetic identical to tracing it.
    bool unoccluded = false;
    std::string reason;  // why, in plain words (for --explain)
};

// POV-Ray's quality levels (+Q, Quality=; its quality flags): what each level renders.
// 9, the default, renders everything povwall has; POV-Ray treats 10 and 11 as 9.
struct Quality {
    int level = 9;
    bool lighting() const { return level >= 2; }  // below: each surface is its pigment
    bool quick_colours() const { return level <= 5; }  // quick_color stands for a pigment
    bool shadows() const { return level >= 4; }
    bool area_lights() const { return level >= 5; }  // below: a point at the centre
    bool refraction() const { return level >= 6; }   // transmitted and refracted rays
    bool reflection() const { return level >= 8; }
    bool normals() const { return level >= 8; }     // normal { } perturbation
    bool atmosphere() const { return level >= 9; }  // fog (and media, radiosity, photons)
    static Quality of(int level) { return {level < 0 ? 0 : level > 9 ? 9 : level}; }
};

struct RenderPlan {
    bool everything_on = false;  // --plan all: nothing is left out
    Quality quality;             // +Q: what the render draws at all
    // Some texture reflects (reflection rays can occur at all).
    bool reflection_rays = true;
    // Some texture lets light through (filter/transmit): transmission and refraction
    // rays, transparent shadow blockers, interior stacks with fade.
    bool transmission_rays = true;
    bool refraction_rays = true;  // a transparent object has an ior other than 1
    std::vector<LightPlan> lights;
    // Shadow rays for points a light does not reach (back faces, outside a spotlight's
    // cone): their contribution is zero, so they are skipped unless everything_on.
    bool skip_unlit_shadow_rays = true;
    // Fewer bounded primitives than this: a flat list instead of an octree (0: always a
    // tree).
    int flat_threshold = 0;
    // Non-linear shading (reflection exponent): black boxes park parents until children
    // report; linear shading forwards contributions straight to the pixel.
    bool parent_tracking = false;
    // Parents must wait whatever --results says: an area light's shadow is the adaptive
    // average of its grid samples, taken once they are all in.
    bool parents_required = false;
    std::string parent_reason;
    // Primitives as the tracer sees them (plain unions opened, mesh triangles counted).
    size_t finite_primitives = 0, infinite_primitives = 0;
};

// `everything_on`: the plan that leaves nothing out (same image, more work).
RenderPlan make_render_plan(const Scene& scene, bool everything_on = false,
                            int quality = 9);

// True when the scene's shading is linear in child colours (no reflection exponent), so
// forward contributions give the same image as parent tracking.
bool shading_is_linear(const Scene& scene);

// Bytes an object will occupy once prepared (primitives, materials, octree references):
// what a box holding it must have room for. Calibrated on
// PreparedScene::resident_bytes().
size_t estimate_prepared_bytes(const Object& object);

// Bytes the parsed object itself occupies (the scene model: Object, its textures, mesh
// lists, CSG children), which a process holding it keeps beside the prepared form.
// Calibrated on the resident memory of `povwall parse` (100,000 spheres: 1.9 KB each).
size_t estimate_model_bytes(const Object& object);

// The plan in plain words, one line per decision ("no transparent materials: refraction
// rays off").
std::vector<std::string> explain_plan(const RenderPlan& plan, const Scene& scene);

}  // namespace povwall::trace
