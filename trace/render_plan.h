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

struct RenderPlan {
    bool everything_on = false;  // --plan all: nothing is left out
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
    std::string parent_reason;
    // Primitives as the tracer sees them (plain unions opened, mesh triangles counted).
    size_t finite_primitives = 0, infinite_primitives = 0;
};

// `everything_on`: the plan that leaves nothing out (same image, more work).
RenderPlan make_render_plan(const Scene& scene, bool everything_on = false);

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
